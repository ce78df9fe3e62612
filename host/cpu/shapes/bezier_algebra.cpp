#include "cpu/shapes/bezier_algebra.hpp"

#include "cpu/lapack.hpp"

#include <algorithm>
#include <cmath>

namespace lancer::cpu::bezier_algebra {
namespace {

constexpr int kN = 6;       // largest Sylvester matrix: 2 x (degree in v)
constexpr int kK = 3 * kN;  // largest pencil: (degree in u) x kN

// beta(3, i, k): the coefficient of x^k in the cubic Bernstein polynomial B_i(x).
constexpr double kBeta[4][4] = {
    {1, -3, 3, -1},  // B_0 = (1-x)^3
    {0, 3, -6, 3},   // B_1 = 3x(1-x)^2
    {0, 0, 3, -3},   // B_2 = 3x^2(1-x)
    {0, 0, 0, 1},    // B_3 = x^3
};

// dggev's workspace, sized once per thread by a workspace query.
std::vector<double>& workspace() {
    thread_local std::vector<double> work;
    if (work.empty()) {
        double a[kK * kK] = {}, b[kK * kK] = {}, ar[kK], ai[kK], be[kK], query = 0.0;
        lapack_int info = lapack_dggev_work()(LAPACK_COL_MAJOR, 'N', 'N', kK, a, kK, b, kK, ar, ai, be, nullptr, 1,
                                             nullptr, 1, &query, -1);
        work.resize(info == 0 ? std::max<std::size_t>(8 * kK, static_cast<std::size_t>(query)) : 64 * kK);
    }
    return work;
}

// The degree in x (0 to 3) that f and g really have together: the highest power of x with a
// coefficient above rounding in either. Degree-elevated patches (every rational quadric) have
// exact zeros there that the transform to ray planes turns into ~1e-16 noise.
int joint_degree(const Bicubic& f, const Bicubic& g, bool in_u, double tol) {
    for (int d = 3; d > 0; --d)
        for (int i = 0; i < 4; ++i) {
            double a = in_u ? f[d][i] : f[i][d], b = in_u ? g[d][i] : g[i][d];
            if (std::abs(a) > tol || std::abs(b) > tol) return d;
        }
    return 0;
}

}  // namespace

Bicubic bernstein_to_power(const std::array<double, 16>& b) {
    Bicubic c{};
    for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l) {
            double sum = 0.0;
            for (int i = 0; i <= k; ++i)
                for (int j = 0; j <= l; ++j) sum += kBeta[i][k] * kBeta[j][l] * b[4 * i + j];
            c[k][l] = sum;
        }
    return c;
}

Value evaluate(const Bicubic& c, double u, double v) {
    // Horner in v for each power of u, then in u, carrying the derivatives along.
    double a[4], av[4];
    for (int k = 0; k < 4; ++k) {
        a[k] = ((c[k][3] * v + c[k][2]) * v + c[k][1]) * v + c[k][0];
        av[k] = (3.0 * c[k][3] * v + 2.0 * c[k][2]) * v + c[k][1];
    }
    Value r;
    r.f = ((a[3] * u + a[2]) * u + a[1]) * u + a[0];
    r.fu = (3.0 * a[3] * u + 2.0 * a[2]) * u + a[1];
    r.fv = ((av[3] * u + av[2]) * u + av[1]) * u + av[0];
    return r;
}

Cubic restrict_to_u(const Bicubic& c, double u) {
    Cubic r{};
    for (int l = 0; l < 4; ++l) r[l] = ((c[3][l] * u + c[2][l]) * u + c[1][l]) * u + c[0][l];
    return r;
}

double horner(const Cubic& c, double x) { return ((c[3] * x + c[2]) * x + c[1]) * x + c[0]; }

double coefficient_norm(const Bicubic& c) {
    double s = 0.0;
    for (const auto& row : c)
        for (double x : row) s += std::abs(x);
    return s;
}

bool resultant_roots(const Bicubic& f, const Bicubic& g, double lo, double hi, std::vector<double>& roots) {
    // The Sylvester matrix must be built for the degree in v that f and g really have: with both
    // leading coefficients zero the formal resultant vanishes identically, the pencil is singular,
    // and dggev's eigenvalues are whatever rounding makes them (they changed with OpenBLAS's
    // kernel). Dropping coefficients at rounding level moves the roots by as little; the caller's
    // Newton polish on the full f and g removes that. The degree in u sets the pencil's size.
    const double tol = 1e-10 * (coefficient_norm(f) + coefficient_norm(g));
    const int dv = joint_degree(f, g, /*in_u=*/false, tol);
    const int du = joint_degree(f, g, /*in_u=*/true, tol);
    if (dv == 0 || du == 0) return true;  // f and g do not both vary: the patch is a curve or a point
    const int n = 2 * dv;                 // Sylvester matrix size
    const int size = du * n;              // pencil size

    // Sylvester matrix in v: Syl(u) [1, v, ..., v^(n-1)]^T = [f, v f, ..., g, v g, ...]^T, split by
    // powers of u as M_0 + u M_1 + ... + u^du M_du; (M_k)[r][r + l] = c_f[k][l], (M_k)[dv + r][r + l] = c_g[k][l].
    double m[4][kN][kN] = {};
    for (int k = 0; k <= du; ++k)
        for (int r = 0; r < dv; ++r)
            for (int l = 0; l <= dv; ++l) {
                m[k][r][r + l] = f[k][l];
                m[k][dv + r][r + l] = g[k][l];
            }
    // First companion form on z = [V; u V; ...; u^(du-1) V]: A z = u B z with
    // A = [[0 I 0 ...], ..., [-M0 -M1 ... -M(du-1)]], B = diag(I, ..., I, M_du). Column-major:
    // X[col * size + row].
    double a[kK * kK] = {}, b[kK * kK] = {};
    for (int p = 0; p + 1 < du; ++p)
        for (int r = 0; r < n; ++r) {
            a[((p + 1) * n + r) * size + p * n + r] = 1.0;
            b[(p * n + r) * size + p * n + r] = 1.0;
        }
    const int last = (du - 1) * n;  // first row and column of the last block
    for (int q = 0; q < du; ++q)
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) a[(q * n + c) * size + last + r] = -m[q][r][c];
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) b[(last + c) * size + last + r] = m[du][r][c];

    double ar[kK], ai[kK], be[kK];
    std::vector<double>& work = workspace();
    lapack_int info = lapack_dggev_work()(LAPACK_COL_MAJOR, 'N', 'N', size, a, size, b, size, ar, ai, be, nullptr, 1,
                                         nullptr, 1, work.data(), static_cast<lapack_int>(work.size()));
    if (info != 0) return false;
    for (int e = 0; e < size; ++e) {
        double scale = std::max({std::abs(ar[e]), std::abs(ai[e]), std::abs(be[e])});
        if (!(scale > 0.0) || !std::isfinite(scale)) continue;  // alpha = beta = 0: singular pencil
        if (std::abs(be[e]) <= 1e-12 * scale) continue;         // infinite: M_du singular
        if (std::abs(ai[e] / be[e]) > 1e-5) continue;           // complex
        double u = ar[e] / be[e];
        if (u >= lo && u <= hi) roots.push_back(u);
    }
    return true;
}

void real_roots(const Cubic& c, double lo, double hi, std::vector<double>& roots) {
    double norm = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]);
    if (!(norm > 0.0) || !std::isfinite(norm)) return;
    int degree = 3;
    // A leading coefficient this small only moves roots that are far outside [0, 1].
    while (degree > 0 && std::abs(c[degree]) <= 1e-14 * norm) --degree;
    if (degree == 0) return;

    // Break [lo, hi] at the critical points, so that c is monotone on each piece.
    double breaks[4];
    int n = 0;
    breaks[n++] = lo;
    double crit[2];
    int ncrit = 0;
    if (degree == 2) {
        crit[ncrit++] = -c[1] / (2.0 * c[2]);
    } else if (degree == 3) {
        double qa = 3.0 * c[3], qb = 2.0 * c[2], qc = c[1];
        double disc = qb * qb - 4.0 * qa * qc;
        if (disc >= 0.0) {
            double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
            crit[ncrit++] = q / qa;
            if (q != 0.0) crit[ncrit++] = qc / q;
            if (ncrit == 2 && crit[0] > crit[1]) std::swap(crit[0], crit[1]);
        }
    }
    for (int i = 0; i < ncrit; ++i)
        if (crit[i] > lo && crit[i] < hi) breaks[n++] = crit[i];
    breaks[n++] = hi;

    for (int i = 0; i + 1 < n; ++i) {
        double a = breaks[i], b = breaks[i + 1];
        double pa = horner(c, a), pb = horner(c, b);
        if (pa == 0.0) {
            roots.push_back(a);
            continue;
        }
        if (pb == 0.0 || (pa < 0.0) == (pb < 0.0)) continue;
        for (int it = 0; it < 200; ++it) {
            double mid = 0.5 * (a + b);
            if (mid <= a || mid >= b) break;
            double pm = horner(c, mid);
            if (pm == 0.0) {
                a = b = mid;
                break;
            }
            if ((pm < 0.0) == (pa < 0.0)) {
                a = mid;
                pa = pm;
            } else {
                b = mid;
            }
        }
        roots.push_back(0.5 * (a + b));
    }
    if (horner(c, hi) == 0.0) roots.push_back(hi);
}

}  // namespace lancer::cpu::bezier_algebra
