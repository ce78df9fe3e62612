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

// Everything the cells depend on, as bytes. Each struct is taken apart by a structured binding,
// which stops compiling when a field is added: a new field must join the key (or be named here
// as one the cells do not depend on), never give stale hits. The nodes' columns only place error
// messages, the surface's derived slot is the renderers', and failures are not cached.
std::string cells_key(const ParametricSurface& s, const CellOptions& options) {
    std::string key;
    const auto& [x, y, z, u0, u1, v0, v1, to_world, derived] = s;
    for (const Expr* e : {&x, &y, &z}) {
        append_bits(key, e->nodes.size());
        for (const Node& n : e->nodes) {
            const auto& [op, a, b, value, column] = n;
            append_bits(key, op);
            append_bits(key, a);
            append_bits(key, b);
            append_bits(key, value);
        }
    }
    for (double d : {u0, u1, v0, v1}) append_bits(key, d);
    const double* m = glm::value_ptr(to_world);
    for (int i = 0; i < 16; ++i) append_bits(key, m[i]);
    const auto& [initial_grid, max_size_fraction, min_regular_fraction, max_depth, max_cells] = options;
    append_bits(key, initial_grid);
    append_bits(key, max_size_fraction);
    append_bits(key, min_regular_fraction);
    append_bits(key, max_depth);
    append_bits(key, max_cells);
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
