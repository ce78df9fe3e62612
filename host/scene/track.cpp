// Keyframe interpolation: Track -> value at a time.
#include <algorithm>
#include <cmath>

#include "scene/animation.hpp"

namespace lancer {
namespace {

struct Key {
    double time;
    dvec3 value;
};

// The cubic Hermite curve from a to b with tangents ma and mb (per unit of clock time), which
// is what makes Catmull-Rom work with unevenly spaced keys.
dvec3 hermite(const Key& a, const Key& b, const dvec3& ma, const dvec3& mb, double time) {
    double dt = b.time - a.time;
    double u = (time - a.time) / dt;
    double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * a.value + (u3 - 2 * u2 + u) * dt * ma + (-2 * u3 + 3 * u2) * b.value +
           (u3 - u2) * dt * mb;
}

long floor_div(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

dvec3 sample(const Track& track, double time, bool cyclic) {
    const auto& times = track.times;
    const long n = static_cast<long>(times.size());
    if (n == 1) return track.values[0];

    // Key j for any integer j. In a cyclic animation the keys repeat with period 1, so the
    // segment after the last key leads to the first key one period later.
    auto key = [&](long j) -> Key {
        if (!cyclic) {
            j = std::clamp(j, 0L, n - 1);
            return {times[j], track.values[j]};
        }
        long wraps = floor_div(j, n);
        long i = j - wraps * n;
        return {times[i] + double(wraps), track.values[i]};
    };

    if (cyclic) {
        time -= std::floor(time);
    } else {
        if (time <= times.front()) return track.values.front();
        if (time >= times.back()) return track.values.back();
    }
    // The segment [key(i), key(i + 1)] holding `time`; i = -1 before the first key (cyclic only).
    long i = static_cast<long>(std::upper_bound(times.begin(), times.end(), time) - times.begin()) - 1;
    Key a = key(i), b = key(i + 1);
    if (track.interpolation == Interpolation::Linear) {
        double u = (time - a.time) / (b.time - a.time);
        return a.value + u * (b.value - a.value);
    }
    // Catmull-Rom tangents from the neighbouring keys; zero at the ends of a non-cyclic track, so
    // the motion starts and stops at rest instead of with a jerk.
    auto tangent = [&](long j) {
        if (!cyclic && (j <= 0 || j >= n - 1)) return dvec3(0.0);
        Key p = key(j - 1), q = key(j + 1);
        return (q.value - p.value) / (q.time - p.time);
    };
    return hermite(a, b, tangent(i), tangent(i + 1), time);
}

}  // namespace lancer
