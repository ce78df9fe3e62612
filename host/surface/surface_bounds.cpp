#include "surface/surface_bounds.hpp"

namespace lancer::surface {
namespace {

// Where the mean-value form is infinite (an unbounded derivative) the natural box alone counts.
IntervalVec3 narrowed(const IntervalVec3& natural, const IntervalVec3& mean_value) {
    IntervalVec3 r = natural;
    for (int i = 0; i < 3; ++i) {
        Interval both = intersect(natural[i], mean_value[i]);
        // An empty intersection can only come from rounding at a point-sized box; keep natural.
        if (!both.is_empty()) r[i] = both;
    }
    return r;
}

IntervalVec3 centre_value(const Program& program, double uc, double vc) {
    Interval c[3];
    evaluate_program(program, Interval(uc), Interval(vc), c);
    return {c[0], c[1], c[2]};
}

// Offsets X - c, outward rounded.
Interval offset(const Interval& x, double c) { return x - Interval(c); }

}  // namespace

BoxBounds bound_surface(const Program& program, const Interval& u, const Interval& v) {
    Dual<Interval> s[3];
    BoxBounds b;
    b.smooth = evaluate_program_on_box(program, u, v, s);
    b.S = {s[0].v, s[1].v, s[2].v};
    b.Su = {s[0].du, s[1].du, s[2].du};
    b.Sv = {s[0].dv, s[1].dv, s[2].dv};
    if (!b.smooth || b.S.is_empty()) return b;
    double uc = u.mid(), vc = v.mid();
    IntervalVec3 c = centre_value(program, uc, vc);
    if (c.is_empty()) return b;
    Interval du = offset(u, uc), dv = offset(v, vc);
    IntervalVec3 mv;
    for (int i = 0; i < 3; ++i) mv[i] = c[i] + b.Su[i] * du + b.Sv[i] * dv;
    b.S = narrowed(b.S, mv);
    return b;
}

SecondPartials bound_second_partials(const Program& program, const Interval& u, const Interval& v) {
    using D2 = Dual<Dual<Interval>>;
    D2 s[3];
    evaluate_program(program, D2::variable_u(Dual<Interval>::variable_u(u)), D2::variable_v(Dual<Interval>::variable_v(v)), s);
    SecondPartials b;
    for (int i = 0; i < 3; ++i) {
        b.Suu[i] = s[i].du.du;
        b.Suv[i] = s[i].du.dv;
        b.Svv[i] = s[i].dv.dv;
    }
    return b;
}

IntervalVec3 transform_vector(const glm::dmat4& m, const IntervalVec3& p) {
    IntervalVec3 r;
    for (int row = 0; row < 3; ++row)
        r[row] = Interval(m[0][row]) * p.x + Interval(m[1][row]) * p.y + Interval(m[2][row]) * p.z;
    return r;
}

IntervalVec3 transform_point(const glm::dmat4& m, const IntervalVec3& p) {
    IntervalVec3 r = transform_vector(m, p);
    for (int row = 0; row < 3; ++row) r[row] = r[row] + Interval(m[3][row]);
    return r;
}

IntervalVec3 world_bounds(const BoxBounds& b, const Program& program, const glm::dmat4& to_world,
                          const Interval& u, const Interval& v) {
    IntervalVec3 natural = transform_point(to_world, b.S);
    if (!b.smooth || natural.is_empty()) return natural;
    double uc = u.mid(), vc = v.mid();
    IntervalVec3 c = centre_value(program, uc, vc);
    if (c.is_empty()) return natural;
    IntervalVec3 wc = transform_point(to_world, c);
    IntervalVec3 wu = transform_vector(to_world, b.Su), wv = transform_vector(to_world, b.Sv);
    Interval du = offset(u, uc), dv = offset(v, vc);
    IntervalVec3 mv;
    for (int i = 0; i < 3; ++i) mv[i] = wc[i] + wu[i] * du + wv[i] * dv;
    return narrowed(natural, mv);
}

}  // namespace lancer::surface
