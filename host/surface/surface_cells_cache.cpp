// surface_cells: subdivide_surface behind a small cache (parametric_cells.hpp says why).
#include <cstring>
#include <list>
#include <mutex>
#include <string>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "surface/parametric_cells.hpp"

namespace lancer::surface {
namespace {

// At most this many cells are kept in all (about 370 bytes each: 24 MiB), and at most
// kMaxSurfaces surfaces; the oldest go first.
constexpr std::size_t kMaxCachedCells = std::size_t{1} << 16;
constexpr std::size_t kMaxSurfaces = 16;

template <class T>
void append_bits(std::string& key, const T& value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    key.append(bytes, sizeof(T));
}

// Everything the cells depend on, as bytes. The nodes' columns are left out: they only place
// error messages, and failures are not cached.
std::string cells_key(const ParametricSurface& s, const CellOptions& options) {
    std::string key;
    for (const Expr* e : {&s.x, &s.y, &s.z}) {
        append_bits(key, e->nodes.size());
        for (const Node& n : e->nodes) {
            append_bits(key, n.op);
            append_bits(key, n.a);
            append_bits(key, n.b);
            append_bits(key, n.value);
        }
    }
    for (double d : {s.u0, s.u1, s.v0, s.v1}) append_bits(key, d);
    const double* m = glm::value_ptr(s.to_world);
    for (int i = 0; i < 16; ++i) append_bits(key, m[i]);
    append_bits(key, options.initial_grid);
    append_bits(key, options.max_size_fraction);
    append_bits(key, options.min_regular_fraction);
    append_bits(key, options.max_depth);
    append_bits(key, options.max_cells);
    return key;
}

using Cells = std::shared_ptr<const std::vector<SurfaceCell>>;

struct Cache {
    std::mutex mutex;
    std::list<std::pair<std::string, Cells>> entries;  // newest first
    std::size_t cells = 0;
};

Cache& cache() {
    static Cache instance;
    return instance;
}

}  // namespace

std::shared_ptr<const std::vector<SurfaceCell>> surface_cells(const ParametricSurface& surface,
                                                              const CellOptions& options) {
    std::string key = cells_key(surface, options);
    Cache& c = cache();
    {
        std::lock_guard lock(c.mutex);
        for (auto it = c.entries.begin(); it != c.entries.end(); ++it) {
            if (it->first != key) continue;
            c.entries.splice(c.entries.begin(), c.entries, it);
            return c.entries.front().second;
        }
    }
    // Cut outside the lock: another thread may cut another surface meanwhile.
    Cells cells = std::make_shared<const std::vector<SurfaceCell>>(subdivide_surface(surface, options));
    if (cells->size() > kMaxCachedCells) return cells;
    std::lock_guard lock(c.mutex);
    for (const auto& [k, kept] : c.entries)
        if (k == key) return kept;  // another thread cut the same surface meanwhile
    c.entries.emplace_front(std::move(key), cells);
    c.cells += cells->size();
    while (c.entries.size() > kMaxSurfaces || c.cells > kMaxCachedCells) {
        c.cells -= c.entries.back().second->size();
        c.entries.pop_back();
    }
    return cells;
}

}  // namespace lancer::surface
