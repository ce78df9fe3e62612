#include "cpu/shapes/polynomial_roots.hpp"

#include <algorithm>
#include <cmath>

#include "cpu/lapack.hpp"

namespace lancer::cpu {

std::vector<ComplexRoot> polynomial_roots(std::span<const double> c) {
    std::vector<ComplexRoot> roots;
    double largest = 0.0;
    for (double x : c) largest = std::max(largest, std::abs(x));
    if (!(largest > 0.0) || !std::isfinite(largest)) return roots;
    std::size_t high = c.size() - 1, low = 0;
    while (high > 0 && !(std::abs(c[high]) > 1e-15 * largest)) --high;
    while (low < high && c[low] == 0.0) {
        roots.push_back({0.0, 0.0});
        ++low;
    }
    const int n = static_cast<int>(high - low);
    if (n == 0) return roots;
    if (n == 1) {
        roots.push_back({-c[low] / c[high], 0.0});
        return roots;
    }
    // Upper Hessenberg companion matrix of the monic polynomial, column-major: the first row is
    // -c[high-1..low] / c[high], ones below the diagonal.
    thread_local std::vector<double> h, wr, wi, work;
    h.assign(std::size_t(n) * n, 0.0);
    wr.resize(n);
    wi.resize(n);
    for (int j = 0; j < n; ++j) h[std::size_t(j) * n] = -c[high - 1 - j] / c[high];
    for (int i = 1; i < n; ++i) h[std::size_t(i - 1) * n + i] = 1.0;
    std::vector<double> scale(n);
    lapack_int ilo = 1, ihi = n;
    // Scaling only: a diagonal similarity keeps the matrix upper Hessenberg for dhseqr.
    if (lapack_dgebal_work()(LAPACK_COL_MAJOR, 'S', n, h.data(), n, &ilo, &ihi, scale.data()) != 0) return roots;
    double query = 0.0;
    lapack_dhseqr_work()(LAPACK_COL_MAJOR, 'E', 'N', n, ilo, ihi, h.data(), n, wr.data(), wi.data(), nullptr, 1,
                        &query, -1);
    work.resize(std::max<std::size_t>(std::size_t(n), static_cast<std::size_t>(query)));
    lapack_int info = lapack_dhseqr_work()(LAPACK_COL_MAJOR, 'E', 'N', n, ilo, ihi, h.data(), n, wr.data(), wi.data(),
                                          nullptr, 1, work.data(), static_cast<lapack_int>(work.size()));
    // info > 0: QR did not converge for some eigenvalues; those before info-1 are still valid,
    // but a root we do not know could be a missed hit, so report what converged and let the
    // caller's certification see the rest as absent (never observed at these sizes).
    int first = info > 0 ? static_cast<int>(info) : 0;
    if (info < 0) return roots;
    for (int i = first; i < n; ++i) roots.push_back({wr[i], wi[i]});
    return roots;
}

}  // namespace lancer::cpu
