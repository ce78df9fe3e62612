// Whether a lathe's curve meets itself (lathe_crossing.hpp).
//
// The curve is cut into items: linear segments as they are; a curved segment into the pieces
// between where r'(s) or y'(s) vanishes (monotone in both, so no piece meets itself), each the
// Bezier curve of its own control points. Item i's `next` is the item whose start is exactly its
// end (the following piece, or the following segment where the spline joins there; the first
// where the curve closes on itself): those two may share that point. Candidate pairs are the
// items whose boxes (of their control points, which hold the curve) overlap, found by a sweep
// along r or y, whichever axis has fewer overlapping intervals (counted first, O(n log n)): O(n
// log n + k) for k pairs overlapping along it, a few per item for a curve that does not crowd
// itself into long parallel strips.
//
// Linear items: exact, by the sign of orientation determinants (a floating-point filter, then
// an exact sum of the products' parts). Curved items: a pair is refined by subdivision (the
// larger half each time): apart where their boxes part, where their chords lie further apart
// than both pieces stray from their chords, or (a pair sharing a joint) where the cones from the
// joint holding their control points meet only there; crossing where each piece's ends lie on
// opposite sides of the other's band about its chord (then each runs across the other's band
// and they cross); else, once both are under the tolerance, they meet (touch or cross).
#include "scene/lathe_crossing.hpp"

#include "scene/bezier_curve.hpp"
#include "scene/limits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace lancer {
namespace lathe_crossing_detail {

using glm::dvec2;

// ---- exact orientation of three points given in double.

void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bv = s - a, av = s - bv;
    e = (a - av) + (b - bv);
}
void two_product(double a, double b, double& p, double& e) {
    p = a * b;
    e = std::fma(a, b, -p);
}

// The sign of (b - a) x (c - a), exact (ignoring overflow and underflow: lathes are within the
// world's extent).
int orientation(const dvec2& a, const dvec2& b, const dvec2& c) {
    const double left = (b.x - a.x) * (c.y - a.y), right = (b.y - a.y) * (c.x - a.x);
    const double det = left - right;
    // Shewchuk's bound for this evaluation, (3 + 16 eps) eps, rounded up.
    const double bound = 3.3306690738754716e-16 * (std::abs(left) + std::abs(right));
    if (det > bound) return 1;
    if (det < -bound) return -1;
    if (left == 0.0 && right == 0.0) {
        // Each product is 0 only where a factor is, and a difference of doubles is 0 only
        // where they are equal: det is exactly 0.
        return 0;
    }
    // Each difference as the exact sum of two doubles, each product of sums as 4 exact products
    // of 2 doubles each: det is the exact sum of 16 doubles, summed into a non-overlapping
    // expansion (Shewchuk's grow-expansion), whose largest part has det's sign.
    double dx1, ex1, dy2, ey2, dy1, ey1, dx2, ex2;
    two_sum(b.x, -a.x, dx1, ex1);
    two_sum(c.y, -a.y, dy2, ey2);
    two_sum(b.y, -a.y, dy1, ey1);
    two_sum(c.x, -a.x, dx2, ex2);
    std::array<double, 16> terms{};
    int count = 0;
    auto add_product = [&](double u, double v, double sign) {
        double p, e;
        two_product(u, v, p, e);
        terms[count++] = sign * p;
        terms[count++] = sign * e;
    };
    for (double u : {dx1, ex1})
        for (double v : {dy2, ey2}) add_product(u, v, 1.0);
    for (double u : {dy1, ey1})
        for (double v : {dx2, ex2}) add_product(u, v, -1.0);
    std::array<double, 40> expansion{};
    int length = 0;
    for (double x : terms) {
        double q = x;
        int kept = 0;
        for (int i = 0; i < length; ++i) {
            double s, e;
            two_sum(q, expansion[i], s, e);
            if (e != 0.0) expansion[kept++] = e;
            q = s;
        }
        if (q != 0.0) expansion[kept++] = q;
        length = kept;
    }
    for (int i = length - 1; i >= 0; --i)
        if (expansion[i] != 0.0) return expansion[i] > 0.0 ? 1 : -1;
    return 0;
}

// Whether c, on the line through a and b, lies on the segment from a to b (exact).
bool within(const dvec2& a, const dvec2& b, const dvec2& c) {
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y && c.y <= std::max(a.y, b.y);
}

// Whether u = p - o and v = q - o, two vectors along one line through o, point the same way (exact).
bool same_way(const dvec2& o, const dvec2& p, const dvec2& q) {
    const int px = (p.x > o.x) - (p.x < o.x), qx = (q.x > o.x) - (q.x < o.x);
    if (px != 0 || qx != 0) return px == qx;
    const int py = (p.y > o.y) - (p.y < o.y), qy = (q.y > o.y) - (q.y < o.y);
    return py == qy && py != 0;
}

// Where the lines through a0, a1 and b0, b1 meet (or a point of the first, where they are parallel).
dvec2 line_meet(const dvec2& a0, const dvec2& a1, const dvec2& b0, const dvec2& b1) {
    const dvec2 da = a1 - a0, db = b1 - b0;
    const double den = da.x * db.y - da.y * db.x;
    if (den == 0.0) return 0.5 * (a0 + a1);
    const double t = ((b0.x - a0.x) * db.y - (b0.y - a0.y) * db.x) / den;
    return a0 + std::clamp(t, 0.0, 1.0) * da;
}

// ---- the items.

struct Item {
    std::size_t segment = 0;
    std::array<dvec2, 4> c{};  // Bezier control points, degree + 1 of them
    dvec2 lo{0.0}, hi{0.0};    // the box of the control points
    long next = -1;            // the item whose start is this one's end (the joint they share)
};

void set_box(Item& item, int n) {
    item.lo = item.hi = item.c[0];
    for (int i = 1; i <= n; ++i) {
        item.lo = glm::min(item.lo, item.c[i]);
        item.hi = glm::max(item.hi, item.c[i]);
    }
}

std::vector<Item> make_items(const Lathe& o) {
    const int n = o.degree;
    std::vector<Item> items;
    for (std::size_t k = 0; k < o.segments.size(); ++k) {
        const LatheSegment& g = o.segments[k];
        std::array<dvec2, 4> c{};
        bool point = true;
        for (int i = 0; i <= n; ++i) {
            c[i] = dvec2(g.r[i], g.y[i]);
            point = point && c[i] == c[0];
        }
        if (point) continue;  // a segment that is a point: its neighbours meet through it
        std::vector<double> cuts = bezier_turning_points(g.r, n);
        for (double s : bezier_turning_points(g.y, n)) cuts.push_back(s);
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        double done = 0.0;
        for (double s : cuts) {
            // The rest of the segment is [done, 1] as c: cut it at s.
            const double t = (s - done) / (1.0 - done);
            if (!(t > 0.0 && t < 1.0)) continue;
            std::array<dvec2, 4> left{}, right{};
            bezier_split(c, n, t, left, right);
            Item item;
            item.segment = k;
            item.c = left;
            items.push_back(item);
            c = right;
            done = s;
        }
        Item item;
        item.segment = k;
        item.c = c;
        items.push_back(item);
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        set_box(items[i], n);
        if (i + 1 < items.size() && items[i].c[n] == items[i + 1].c[0]) items[i].next = long(i + 1);
    }
    if (items.size() > 1 && items.back().c[n] == items.front().c[0]) items.back().next = 0;
    return items;
}

// ---- linear items: exact.

std::optional<dvec2> segments_meet(const dvec2& p0, const dvec2& p1, const dvec2& q0, const dvec2& q1) {
    const int o1 = orientation(p0, p1, q0), o2 = orientation(p0, p1, q1);
    const int o3 = orientation(q0, q1, p0), o4 = orientation(q0, q1, p1);
    if (o1 * o2 < 0 && o3 * o4 < 0) return line_meet(p0, p1, q0, q1);
    if (o1 == 0 && within(p0, p1, q0)) return q0;
    if (o2 == 0 && within(p0, p1, q1)) return q1;
    if (o3 == 0 && within(q0, q1, p0)) return p0;
    if (o4 == 0 && within(q0, q1, p1)) return p1;
    return std::nullopt;
}

// Segments a and b, where a's end is b's start (the joint p): they meet elsewhere only where
// they lie along one line and leave p the same way (the curve turns back over itself).
std::optional<dvec2> joined_segments_meet(const dvec2& a0, const dvec2& p, const dvec2& b1) {
    if (orientation(a0, p, b1) == 0 && same_way(p, a0, b1)) return p;
    return std::nullopt;
}

// ---- linear items: Shamos and Hoey's sweep (any two segments that meet are found), exact.
//
// Events in the lexicographic order of (y, r) (a sweep line tilted infinitely little, so that a
// level segment is as any other); each segment runs from its lower end to its upper. The segments
// the line crosses are kept in their order along it, compared where the later of the two starts
// (which side of the other its lower end lies, exactly): valid while no two have met, and the
// sweep stops at the first meeting it finds. A segment is tested against its neighbours when it
// enters, and the neighbours of one that leaves against each other: the lowest meeting is found
// before the line passes it. Ends shared other than at a joint are found first, from the sorted ends.

bool before(const dvec2& a, const dvec2& b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }

struct Sweep {
    const std::vector<Item>& items;
    std::vector<dvec2> lo, hi;
    std::optional<dvec2> found;  // where a comparison found two segments meeting
    std::size_t found_a = 0, found_b = 0;

    explicit Sweep(const std::vector<Item>& all) : items(all), lo(all.size()), hi(all.size()) {
        for (std::size_t i = 0; i < all.size(); ++i) {
            const bool up = before(all[i].c[0], all[i].c[1]);
            lo[i] = up ? all[i].c[0] : all[i].c[1];
            hi[i] = up ? all[i].c[1] : all[i].c[0];
        }
    }

    // Whether segment x lies left of segment y along the sweep line, x starting no earlier.
    bool left_of_later(std::size_t x, std::size_t y) {
        int o = orientation(lo[y], hi[y], lo[x]);
        if (o == 0) {
            if (lo[x] != lo[y] || orientation(lo[y], hi[y], hi[x]) == 0) {
                // x starts on y (not at its ends: those were checked), or they start together
                // along one line (they overlap).
                if (!found) found = lo[x], found_a = x, found_b = y;
                return x < y;
            }
            o = orientation(lo[y], hi[y], hi[x]);
        }
        return o > 0;
    }
    bool less(std::size_t x, std::size_t y) {
        if (x == y) return false;
        if (!before(lo[x], lo[y])) return left_of_later(x, y);
        return !left_of_later(y, x);
    }

    std::optional<dvec2> test(std::size_t i, std::size_t j) const {
        const Item &a = items[i], &b = items[j];
        const bool ab = a.next == long(j), ba = b.next == long(i);
        if (ab && ba) return 0.5 * (a.c[0] + a.c[1]);  // two segments, one the other reversed
        if (ab) return joined_segments_meet(a.c[0], a.c[1], b.c[1]);
        if (ba) return joined_segments_meet(b.c[0], b.c[1], a.c[1]);
        return segments_meet(a.c[0], a.c[1], b.c[0], b.c[1]);
    }
};

struct SweepLess {
    Sweep* sweep;
    bool operator()(std::size_t x, std::size_t y) const { return sweep->less(x, y); }
};

std::optional<std::pair<std::size_t, dvec2>> sweep_meeting(const std::vector<Item>& items, std::size_t& other) {
    const std::size_t count = items.size();
    Sweep sweep(items);
    // The ends: where ends coincide, they must be the two of one joint.
    struct End {
        dvec2 p;
        std::size_t item;
        bool upper;
    };
    std::vector<End> ends;
    ends.reserve(2 * count);
    for (std::size_t i = 0; i < count; ++i) {
        ends.push_back({sweep.lo[i], i, false});
        ends.push_back({sweep.hi[i], i, true});
    }
    std::sort(ends.begin(), ends.end(), [](const End& a, const End& b) {
        if (a.p != b.p) return before(a.p, b.p);
        return a.upper && !b.upper;  // leaving before entering
    });
    for (std::size_t k = 0; k < ends.size();) {
        std::size_t m = k + 1;
        while (m < ends.size() && ends[m].p == ends[k].p) ++m;
        const bool joint = m - k == 2 && (items[ends[k].item].next == long(ends[k + 1].item) ||
                                          items[ends[k + 1].item].next == long(ends[k].item));
        if (m - k > 2 || (m - k == 2 && !joint)) {
            other = ends[k + 1].item;
            return std::make_pair(ends[k].item, ends[k].p);
        }
        k = m;
    }
    std::set<std::size_t, SweepLess> line{SweepLess{&sweep}};
    std::vector<std::set<std::size_t, SweepLess>::iterator> where(count, line.end());
    for (const End& e : ends) {
        if (e.upper) {
            const auto at = where[e.item];
            if (at != line.begin() && std::next(at) != line.end()) {
                const std::size_t below = *std::prev(at), above = *std::next(at);
                if (auto meet = sweep.test(below, above)) {
                    other = above;
                    return std::make_pair(below, *meet);
                }
            }
            line.erase(at);
            where[e.item] = line.end();
        } else {
            const auto at = line.insert(e.item).first;
            if (sweep.found) {  // it starts on another, or along one
                other = sweep.found_b;
                return std::make_pair(sweep.found_a, *sweep.found);
            }
            where[e.item] = at;
            for (auto neighbour : {at == line.begin() ? line.end() : std::prev(at), std::next(at)})
                if (neighbour != line.end())
                    if (auto meet = sweep.test(e.item, *neighbour)) {
                        other = *neighbour;
                        return std::make_pair(e.item, *meet);
                    }
        }
    }
    return std::nullopt;
}

// ---- curved items: refined.

struct Piece {
    std::array<dvec2, 4> c{};
    bool has_start = true, has_end = true;  // whether it reaches its item's start, end
};

struct Refiner {
    int n;
    double tolerance;
    double margin;
    int steps = 0;

    static double box_size(const Piece& p, int n, dvec2& lo, dvec2& hi) {
        lo = hi = p.c[0];
        for (int i = 1; i <= n; ++i) {
            lo = glm::min(lo, p.c[i]);
            hi = glm::max(hi, p.c[i]);
        }
        return std::max(hi.x - lo.x, hi.y - lo.y);
    }

    // How far the piece strays from its chord (its control points' greatest distance from the
    // segment between its ends); infinite where the chord is a point.
    double stray(const Piece& p) const {
        const dvec2 a = p.c[0], d = p.c[n] - p.c[0];
        const double dd = glm::dot(d, d);
        if (!(dd > 0.0)) return INFINITY;
        double most = 0.0;
        for (int i = 1; i < n; ++i) {
            const double t = std::clamp(glm::dot(p.c[i] - a, d) / dd, 0.0, 1.0);
            most = std::max(most, glm::length(p.c[i] - (a + t * d)));
        }
        return most;
    }

    static double point_segment(const dvec2& p, const dvec2& a, const dvec2& b) {
        const dvec2 d = b - a;
        const double dd = glm::dot(d, d);
        const double t = dd > 0.0 ? std::clamp(glm::dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
        return glm::length(p - (a + t * d));
    }
    static double chords_apart(const dvec2& a0, const dvec2& a1, const dvec2& b0, const dvec2& b1) {
        const int o1 = orientation(a0, a1, b0), o2 = orientation(a0, a1, b1);
        const int o3 = orientation(b0, b1, a0), o4 = orientation(b0, b1, a1);
        if (o1 * o2 <= 0 && o3 * o4 <= 0) return 0.0;
        return std::min({point_segment(a0, b0, b1), point_segment(a1, b0, b1), point_segment(b0, a0, a1),
                         point_segment(b1, a0, a1)});
    }

    // Whether p's ends lie beyond the band of half-width e about q's chord, on opposite sides.
    bool across(const Piece& p, const Piece& q, double e) const {
        const dvec2 d = q.c[n] - q.c[0];
        const double length = glm::length(d);
        if (!(length > 0.0)) return false;
        auto side = [&](const dvec2& x) { return (d.x * (x.y - q.c[0].y) - d.y * (x.x - q.c[0].x)) / length; };
        const double s0 = side(p.c[0]), s1 = side(p.c[n]);
        const double limit = e + margin;
        return (s0 > limit && s1 < -limit) || (s0 < -limit && s1 > limit);
    }

    // The angular interval, about the joint j, holding the piece's control points other than j:
    // its middle direction and half-width; false where it is half a turn or more.
    bool cone(const Piece& p, const dvec2& j, double& middle, double& half) const {
        dvec2 reference{0.0};
        for (int i = 0; i <= n; ++i)
            if (p.c[i] != j) {
                reference = p.c[i] - j;
                break;
            }
        if (reference == dvec2(0.0)) return false;
        double lo = 0.0, hi = 0.0;
        for (int i = 0; i <= n; ++i) {
            if (p.c[i] == j) continue;
            const dvec2 u = p.c[i] - j;
            const double angle = std::atan2(reference.x * u.y - reference.y * u.x, glm::dot(reference, u));
            lo = std::min(lo, angle);
            hi = std::max(hi, angle);
        }
        if (!(hi - lo < M_PI)) return false;
        middle = std::atan2(reference.y, reference.x) + 0.5 * (lo + hi);
        half = 0.5 * (hi - lo);
        return true;
    }
    // Whether pieces a and b, which share only the joint j, meet only there: the cones from j
    // holding them (their control points) meet only at j.
    bool apart_at_joint(const Piece& a, const Piece& b, const dvec2& j) const {
        double ma, ha, mb, hb;
        if (!cone(a, j, ma, ha) || !cone(b, j, mb, hb)) return false;
        double d = std::remainder(mb - ma, 2.0 * M_PI);
        return std::abs(d) > ha + hb + 1e-12;
    }

    // a's end is b's start where ab (a joint of the curve), b's end a's start where ba.
    std::optional<dvec2> meet(const Piece& a, const Piece& b, bool ab, bool ba, int depth) {
        ++steps;
        dvec2 alo, ahi, blo, bhi;
        const double asize = box_size(a, n, alo, ahi), bsize = box_size(b, n, blo, bhi);
        if (alo.x > bhi.x || blo.x > ahi.x || alo.y > bhi.y || blo.y > ahi.y) return std::nullopt;
        ab = ab && a.has_end && b.has_start;
        ba = ba && b.has_end && a.has_start;
        if (ab != ba) {
            if (ab ? apart_at_joint(a, b, b.c[0]) : apart_at_joint(a, b, a.c[0])) return std::nullopt;
        } else if (!ab) {
            const double ea = stray(a), eb = stray(b);
            if (std::isfinite(ea) && std::isfinite(eb)) {
                if (chords_apart(a.c[0], a.c[n], b.c[0], b.c[n]) > ea + eb + margin) return std::nullopt;
                if (across(a, b, eb) && across(b, a, ea)) return line_meet(a.c[0], a.c[n], b.c[0], b.c[n]);
            }
        }
        if ((asize < tolerance && bsize < tolerance) || depth > 200) {
            if (ab || ba) return std::nullopt;  // at the joint they share, within the tolerance
            return 0.5 * (a.c[0] + a.c[n]);
        }
        const bool cut_a = asize >= bsize;
        const Piece& whole = cut_a ? a : b;
        Piece left, right;
        bezier_split(whole.c, n, 0.5, left.c, right.c);
        left.has_start = whole.has_start;
        left.has_end = false;
        right.has_start = false;
        right.has_end = whole.has_end;
        for (const Piece* half : {&left, &right}) {
            const auto at = cut_a ? meet(*half, b, ab, ba, depth + 1) : meet(a, *half, ab, ba, depth + 1);
            if (at) return at;
        }
        return std::nullopt;
    }
};

}  // namespace lathe_crossing_detail

std::optional<LatheSelfCrossing> find_lathe_crossing(const Lathe& o) {
    using namespace lathe_crossing_detail;
    const int n = o.degree;
    const std::vector<Item> items = make_items(o);
    const std::size_t count = items.size();
    if (count < 2) return std::nullopt;
    auto crossing_of = [&](std::size_t i, std::size_t j, const dvec2& at) {
        LatheSelfCrossing crossing;
        crossing.first = std::min(items[i].segment, items[j].segment);
        crossing.second = std::max(items[i].segment, items[j].segment);
        crossing.near = at;
        return crossing;
    };
    if (n == 1) {
        std::size_t other = 0;
        if (const auto meeting = sweep_meeting(items, other)) return crossing_of(meeting->first, other, meeting->second);
        return std::nullopt;
    }

    // The sweep's axis: where fewer boxes overlap as intervals.
    auto overlaps_along = [&](int axis) {
        std::vector<double> los(count), his(count);
        for (std::size_t i = 0; i < count; ++i) {
            los[i] = items[i].lo[axis];
            his[i] = items[i].hi[axis];
        }
        std::vector<double> sorted_lo = los, sorted_hi = his;
        std::sort(sorted_lo.begin(), sorted_lo.end());
        std::sort(sorted_hi.begin(), sorted_hi.end());
        double pairs = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
            // Intervals starting at or before i's end, less those ending before its start, less itself.
            const auto starting = std::upper_bound(sorted_lo.begin(), sorted_lo.end(), his[i]) - sorted_lo.begin();
            const auto ended = std::lower_bound(sorted_hi.begin(), sorted_hi.end(), los[i]) - sorted_hi.begin();
            pairs += double(starting - ended - 1);
        }
        return pairs / 2.0;
    };
    const double pairs_along_r = overlaps_along(0), pairs_along_y = overlaps_along(1);
    const int axis = pairs_along_r <= pairs_along_y ? 0 : 1, other = 1 - axis;
    if (std::min(pairs_along_r, pairs_along_y) > limits::kMaxLatheCrossingPairs) {
        LatheSelfCrossing crowded;
        crowded.crowded = std::min(pairs_along_r, pairs_along_y);
        return crowded;
    }
    std::vector<std::size_t> order(count);
    for (std::size_t i = 0; i < count; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return items[a].lo[axis] < items[b].lo[axis]; });

    double size = 0.0;
    for (const Item& item : items)
        size = std::max({size, std::abs(item.lo.x), std::abs(item.lo.y), std::abs(item.hi.x), std::abs(item.hi.y)});
    // Curved pieces closer than 1e-9 of the curve's size are taken to meet (a touch within rounding).
    Refiner refiner{n, 1e-9 * size, 1e-13 * size};

    for (std::size_t u = 0; u < count; ++u) {
        const std::size_t i = order[u];
        const Item& a = items[i];
        for (std::size_t v = u + 1; v < count && items[order[v]].lo[axis] <= a.hi[axis]; ++v) {
            const std::size_t j = order[v];
            const Item& b = items[j];
            if (b.lo[other] > a.hi[other] || a.lo[other] > b.hi[other]) continue;
            Piece pa, pb;
            pa.c = a.c;
            pb.c = b.c;
            if (const auto at = refiner.meet(pa, pb, a.next == long(j), b.next == long(i), 0)) return crossing_of(i, j, *at);
        }
    }
    return std::nullopt;
}

}  // namespace lancer
