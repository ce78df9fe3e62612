#include "mesh/ply_reader.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "mesh/mesh_assembly.hpp"
#include "mesh/mesh_limits.hpp"
#include "mesh/ply_header.hpp"
#include "mesh/ply_values.hpp"
#include "mesh/text_lines.hpp"

namespace lancer::mesh {
namespace {

constexpr int kNoSlot = kNoProperty;

// Where each vertex property goes: 0-2 position, 3-5 normal, 6-7 texture coordinate.
struct VertexLayout {
    std::vector<int> slot;  // per property
    bool normals = false, uvs = false;
};

class PlyReader {
public:
    PlyReader(std::string_view bytes, const std::string& name)
        : file_(name), header_(read_ply_header(bytes, name)), values_(bytes, header_, name) {}

    TriangleMesh read() {
        for (const PlyElement& e : header_.elements) {
            if (e.name == "vertex" && e.count > kMaxMeshVertices)
                fail_in_header(e.line, fmt::format("{} vertices are more than lancer's limit of {} (32-bit indices)", e.count,
                                                   kMaxMeshVertices));
            values_.refuse_what_cannot_fit(e);
            if (e.name == "vertex")
                read_vertices(e);
            else if (e.name == "face" || e.name == "tristrips")
                read_polygons(e, e.name == "tristrips");
            else
                values_.skip_element(e);
        }
        values_.require_end();
        require_triangles(mesh_, file_);
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail_in_header(int line, const std::string& message) const { throw SceneError({file_, line, 0}, message); }

    VertexLayout vertex_layout(const PlyElement& e) const {
        VertexLayout layout;
        layout.slot.assign(e.properties.size(), kNoSlot);
        const int xyz[3] = {find_scalar(e, {"x"}), find_scalar(e, {"y"}), find_scalar(e, {"z"})};
        for (int i = 0; i < 3; ++i) {
            if (xyz[i] == kNoSlot)
                fail_in_header(e.line, fmt::format("the vertex element has no scalar property {}", "xyz"[i]));
            layout.slot[xyz[i]] = i;
        }
        const int n[3] = {find_scalar(e, {"nx"}), find_scalar(e, {"ny"}), find_scalar(e, {"nz"})};
        const int normals = (n[0] != kNoSlot) + (n[1] != kNoSlot) + (n[2] != kNoSlot);
        if (normals != 0 && normals != 3) fail_in_header(e.line, "the vertex element has some of nx ny nz but not all three");
        layout.normals = normals == 3;
        if (layout.normals)
            for (int i = 0; i < 3; ++i) layout.slot[n[i]] = 3 + i;
        const int u = find_scalar(e, {"u", "s", "texture_u", "texture_s"}), v = find_scalar(e, {"v", "t", "texture_v", "texture_t"});
        if ((u == kNoSlot) != (v == kNoSlot))
            fail_in_header(e.line, "the vertex element has only one texture coordinate (u v, s t or texture_u texture_v)");
        layout.uvs = u != kNoSlot;
        if (layout.uvs) {
            layout.slot[u] = 6;
            layout.slot[v] = 7;
        }
        return layout;
    }

    void read_vertices(const PlyElement& e) {
        if (seen_vertices_) fail_in_header(e.line, "a second vertex element");
        seen_vertices_ = true;
        const VertexLayout layout = vertex_layout(e);
        const std::size_t capacity = values_.capacity_for(e);
        mesh_.positions.reserve(capacity);
        if (layout.normals) mesh_.normals.reserve(capacity);
        if (layout.uvs) mesh_.uvs.reserve(capacity);
        double slots[8] = {};
        for (std::uint64_t k = 0; k < e.count; ++k) {
            values_.read_scalars(e, k, layout.slot, [&](int slot, const PlyProperty& p, double x) {
                // Normals are scaled to unit length; only positions and texture coordinates need lancer's range.
                if (slot < 3 || slot >= 6) {
                    if (auto problem = coordinate_problem(x)) values_.fail(fmt::format("vertex {}: {} {}", k, p.name, *problem));
                } else if (!std::isfinite(x)) {
                    values_.fail(fmt::format("vertex {}: {} is not a finite number", k, p.name));
                }
                slots[slot] = x;
            });
            mesh_.positions.emplace_back(slots[0], slots[1], slots[2]);
            if (layout.normals) {
                const auto unit = unit_normal({slots[3], slots[4], slots[5]});
                if (!unit) values_.fail(fmt::format("vertex {}: the normal has zero length: it gives no direction", k));
                mesh_.normals.push_back(*unit);
            }
            if (layout.uvs) mesh_.uvs.emplace_back(slots[6], slots[7]);
        }
    }

    const PlyProperty& index_list(const PlyElement& e) const {
        const PlyProperty* found = nullptr;
        for (const PlyProperty& p : e.properties)
            if (p.name == "vertex_indices" || p.name == "vertex_index") {
                if (found) fail_in_header(p.line, fmt::format("the {} element has two lists of vertex indices", e.name));
                found = &p;
            }
        if (!found) fail_in_header(e.line, fmt::format("the {} element has no list vertex_indices (or vertex_index)", e.name));
        if (!found->is_list) fail_in_header(found->line, fmt::format("{} must be a list", found->name));
        if (!is_integer(found->type))
            fail_in_header(found->line, fmt::format("{} must hold integers, not {}", found->name, name_of(found->type)));
        return *found;
    }

    std::uint32_t vertex_index(std::int64_t i, const char* element, std::uint64_t k) {
        if (i < 0 || static_cast<std::uint64_t>(i) >= mesh_.positions.size())
            values_.fail(fmt::format("{} {}: vertex index {} is out of range: the file has {} vertices", element, k, i,
                                     mesh_.positions.size()));
        return static_cast<std::uint32_t>(i);
    }

    void read_polygons(const PlyElement& e, bool strips) {
        const PlyProperty& indices = index_list(e);
        if (!seen_vertices_) fail_in_header(e.line, fmt::format("the {} element comes before the vertex element", e.name));
        mesh_.triangles.reserve(mesh_.triangles.size() + values_.capacity_for(e));
        TriangleFan fan(mesh_);
        const char* what = strips ? "strip" : "face";
        for (std::uint64_t k = 0; k < e.count; ++k) {
            values_.set_item(e.name, k, e.count);
            for (const PlyProperty& p : e.properties) {
                if (&p != &indices) {
                    p.is_list ? values_.skip_list(p) : values_.skip(p.type);
                    continue;
                }
                const std::uint64_t n = values_.list_length(p);
                if (strips) {
                    read_strip(p, n, k, fan);
                    continue;
                }
                if (n < 3) values_.fail(fmt::format("face {} has {} corners: a face needs at least 3", k, n));
                polygon_.clear();
                for (std::uint64_t i = 0; i < n; ++i) polygon_.push_back(vertex_index(values_.integer(p.type), what, k));
                fan.add_polygon(polygon_, std::nullopt);
            }
        }
    }

    // Triangle i of a strip is (s_i, s_i+1, s_i+2), turned around for odd i so that all face one way.
    void read_strip(const PlyProperty& p, std::uint64_t n, std::uint64_t k, TriangleFan& fan) {
        std::uint32_t last[2] = {0, 0};  // the two corners before the next
        int have = 0;
        bool odd = false;
        for (std::uint64_t i = 0; i < n; ++i) {
            const std::int64_t raw = values_.integer(p.type);
            if (raw == -1) {  // a restart
                have = 0;
                odd = false;
                continue;
            }
            const std::uint32_t c = vertex_index(raw, "strip", k);
            if (have < 2) {
                last[have++] = c;
                continue;
            }
            odd ? fan.add_triangle(last[1], last[0], c, std::nullopt) : fan.add_triangle(last[0], last[1], c, std::nullopt);
            odd = !odd;
            last[0] = last[1];
            last[1] = c;
        }
    }

    std::string file_;
    PlyHeader header_;
    PlyValues values_;
    TriangleMesh mesh_;
    std::vector<std::uint32_t> polygon_;
    bool seen_vertices_ = false;
};

}  // namespace

TriangleMesh read_ply(std::string_view bytes, const std::string& name) { return PlyReader(bytes, name).read(); }

}  // namespace lancer::mesh
