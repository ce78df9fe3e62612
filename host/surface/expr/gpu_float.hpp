#pragma once
// A float that computes as the shader does: the GLSL the emitter writes (glsl_emitter.cpp),
// compiled to SPIR-V's GLSL.std.450 and lowered as Mesa lowers it. Where that differs from
// double, it is not only precision: 1e40 is infinity, hypot(a, b) is length(vec2(a, b)) and
// overflows once a * a does, asinh(x) is log(x + sqrt(x * x + 1)). Evaluating a surface with
// Dual<GpuFloat> tells, before anything is rendered, whether the GPU can evaluate it where the
// double reference can (surface/float_check.hpp).
#include <cmath>
#include <limits>

#include "surface/dual.hpp"

namespace lancer::surface {

struct GpuFloat {
    float x = 0.0f;
    GpuFloat() = default;
    explicit GpuFloat(double value) : x(static_cast<float>(value)) {}
    static GpuFloat of(float value) {
        GpuFloat g;
        g.x = value;
        return g;
    }
};

inline GpuFloat operator+(GpuFloat a, GpuFloat b) { return GpuFloat::of(a.x + b.x); }
inline GpuFloat operator-(GpuFloat a, GpuFloat b) { return GpuFloat::of(a.x - b.x); }
inline GpuFloat operator*(GpuFloat a, GpuFloat b) { return GpuFloat::of(a.x * b.x); }
inline GpuFloat operator/(GpuFloat a, GpuFloat b) { return GpuFloat::of(a.x / b.x); }
inline GpuFloat operator-(GpuFloat a) { return GpuFloat::of(-a.x); }

namespace gpu_float {
inline GpuFloat f(float x) { return GpuFloat::of(x); }
inline float sign(float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); }
}  // namespace gpu_float

inline GpuFloat sqr(GpuFloat a) { return a * a; }
inline GpuFloat min(GpuFloat a, GpuFloat b) { return GpuFloat::of(std::fmin(a.x, b.x)); }
inline GpuFloat max(GpuFloat a, GpuFloat b) { return GpuFloat::of(std::fmax(a.x, b.x)); }
inline GpuFloat abs(GpuFloat a) { return GpuFloat::of(std::fabs(a.x)); }
inline GpuFloat sqrt(GpuFloat a) { return GpuFloat::of(std::sqrt(a.x)); }
inline GpuFloat exp(GpuFloat a) { return GpuFloat::of(std::exp(a.x)); }
inline GpuFloat exp2(GpuFloat a) { return GpuFloat::of(std::exp2(a.x)); }
inline GpuFloat log(GpuFloat a) { return GpuFloat::of(std::log(a.x)); }
inline GpuFloat log2(GpuFloat a) { return GpuFloat::of(std::log2(a.x)); }
inline GpuFloat log10(GpuFloat a) { return GpuFloat::of(std::log(a.x) * static_cast<float>(1.0 / std::log(10.0))); }
inline GpuFloat sin(GpuFloat a) { return GpuFloat::of(std::sin(a.x)); }
inline GpuFloat cos(GpuFloat a) { return GpuFloat::of(std::cos(a.x)); }
inline GpuFloat tan(GpuFloat a) { return GpuFloat::of(std::sin(a.x) / std::cos(a.x)); }
inline GpuFloat asin(GpuFloat a) { return GpuFloat::of(std::asin(a.x)); }
inline GpuFloat acos(GpuFloat a) { return GpuFloat::of(std::acos(a.x)); }
inline GpuFloat atan(GpuFloat a) { return GpuFloat::of(std::atan(a.x)); }
inline GpuFloat atan2(GpuFloat y, GpuFloat x) { return GpuFloat::of(std::atan2(y.x, x.x)); }
// GLSL.std.450 as Mesa lowers it (spirv/vtn_glsl450.c): the exponential forms.
inline GpuFloat sinh(GpuFloat a) { return GpuFloat::of(0.5f * (std::exp(a.x) - std::exp(-a.x))); }
inline GpuFloat cosh(GpuFloat a) { return GpuFloat::of(0.5f * (std::exp(a.x) + std::exp(-a.x))); }
inline GpuFloat tanh(GpuFloat a) {
    const float x = std::fmin(std::fmax(a.x, -10.0f), 10.0f);  // Mesa clamps, so that e^2x stays finite
    const float e = std::exp(2.0f * x);
    return GpuFloat::of((e - 1.0f) / (e + 1.0f));
}
inline GpuFloat asinh(GpuFloat a) {
    return GpuFloat::of(gpu_float::sign(a.x) * std::log(std::fabs(a.x) + std::sqrt(a.x * a.x + 1.0f)));
}
inline GpuFloat acosh(GpuFloat a) { return GpuFloat::of(std::log(a.x + std::sqrt(a.x * a.x - 1.0f))); }
inline GpuFloat atanh(GpuFloat a) { return GpuFloat::of(0.5f * std::log((1.0f + a.x) / (1.0f - a.x))); }
inline GpuFloat hypot(GpuFloat a, GpuFloat b) { return GpuFloat::of(std::sqrt(a.x * a.x + b.x * b.x)); }  // length(vec2)
inline GpuFloat cbrt(GpuFloat a) { return GpuFloat::of(gpu_float::sign(a.x) * std::pow(std::fabs(a.x), 1.0f / 3.0f)); }
// pow(x, y) is exp2(y * log2(x)): undefined for x < 0, as in double here (scalar_ops.hpp).
inline GpuFloat powr(GpuFloat a, GpuFloat b) {
    if (a.x > 0.0f) return GpuFloat::of(std::exp2(b.x * std::log2(a.x)));
    if (a.x == 0.0f && b.x > 0.0f) return GpuFloat::of(0.0f);
    return GpuFloat::of(std::numeric_limits<float>::quiet_NaN());
}
inline GpuFloat powc(GpuFloat a, double c) {
    return a.x >= 0.0f ? powr(a, GpuFloat(c)) : GpuFloat::of(std::numeric_limits<float>::quiet_NaN());
}
// integer_power() in the emitter: products up to the 4th power, else pow(abs(x), m) with the sign.
inline GpuFloat powi(GpuFloat a, int n) {
    if (n < 0) return GpuFloat::of(1.0f) / powi(a, -n);
    if (n == 0) return GpuFloat::of(1.0f);
    if (n <= 4) {
        GpuFloat p = a;
        for (int i = 1; i < n; ++i) p = p * a;
        return p;
    }
    GpuFloat m = GpuFloat::of(std::exp2(static_cast<float>(n) * std::log2(std::fabs(a.x))));
    if (n % 2 == 0) return m;
    return a.x == 0.0f ? GpuFloat::of(0.0f) : a * GpuFloat::of(std::exp2(static_cast<float>(n - 1) * std::log2(std::fabs(a.x))));
}

// The kinks, as the emitter's: sign(x), and the derivative of the argument min/max return.
inline Dual<GpuFloat> abs(const Dual<GpuFloat>& x) {
    return chain(abs(x.v), GpuFloat::of(gpu_float::sign(x.v.x)), x);
}
inline Dual<GpuFloat> min(const Dual<GpuFloat>& a, const Dual<GpuFloat>& b) { return a.v.x < b.v.x ? a : b; }
inline Dual<GpuFloat> max(const Dual<GpuFloat>& a, const Dual<GpuFloat>& b) { return a.v.x > b.v.x ? a : b; }

}  // namespace lancer::surface
