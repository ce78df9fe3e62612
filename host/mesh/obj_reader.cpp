#include "mesh/obj_reader.hpp"

#include <filesystem>
#include <optional>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "mesh/mesh_assembly.hpp"
#include "mesh/mesh_file.hpp"
#include "mesh/mesh_limits.hpp"
#include "mesh/text_lines.hpp"

namespace lancer::mesh {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

struct Corner {
    std::uint32_t v = kNone, vt = kNone, vn = kNone;
    bool operator==(const Corner&) const = default;
};

struct CornerHash {
    std::size_t operator()(const Corner& c) const {
        return std::hash<std::uint64_t>()((std::uint64_t(c.v) << 32 | c.vt) ^ (std::uint64_t(c.vn) * 0x9E3779B97F4A7C15ull));
    }
};

bool is_free_form(std::string_view key) {
    for (std::string_view k : {"vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole",
                               "scrv", "sp", "end", "con"})
        if (key == k) return true;
    return false;
}

bool is_passed_over(std::string_view key) {
    for (std::string_view k : {"o", "g", "s", "mg", "l", "p", "bevel", "c_interp", "d_interp", "lod", "maplib", "usemap",
                               "shadow_obj", "trace_obj", "ctech", "stech"})
        if (key == k) return true;
    return false;
}

class ObjReader {
public:
    ObjReader(std::string_view text, const std::string& name, const ObjCompanions& companions)
        : lines_(text, name), companions_(companions) {}

    TriangleMesh read() {
        while (lines_.next()) statement();
        if (first_face_line_ != 0 && !faces_have_uv_ && !faces_have_normal_) take_positions_up_to(positions_.size());
        assign_default_material();
        require_triangles(mesh_, lines_.file());
        return std::move(mesh_);
    }

private:
    void statement() {
        const auto& tok = lines_.tokens();
        const std::string_view key = tok[0].text;
        if (key == "v") {
            if (tok.size() < 4 || tok.size() > 8) lines_.fail(tok[0], "a vertex needs x y z (and at most a w or r g b after them)");
            positions_.push_back(coordinates<3>("vertex coordinate", 3));
        } else if (key == "vt") {
            if (tok.size() < 2 || tok.size() > 4) lines_.fail(tok[0], "a texture coordinate needs u [v [w]]");
            glm::dvec2 uv{0.0};
            for (std::size_t i = 1; i < std::min<std::size_t>(tok.size(), 3); ++i) uv[i - 1] = coordinate(tok[i], "texture coordinate");
            if (tok.size() == 4) coordinate(tok[3], "texture coordinate");
            uvs_.push_back(uv);
        } else if (key == "vn") {
            if (tok.size() != 4) lines_.fail(tok[0], "a normal needs x y z");
            const glm::dvec3 n = coordinates<3>("normal coordinate", 3);
            const auto unit = unit_normal(n);
            if (!unit) lines_.fail(tok[1], "the normal has zero length: it gives no direction");
            normals_.push_back(*unit);
        } else if (key == "f" || key == "fo") {
            face();
        } else if (key == "usemtl") {
            use_material();
        } else if (key == "mtllib") {
            if (tok.size() < 2) lines_.fail_after_last("mtllib needs a file name");
            for (std::size_t i = 1; i < tok.size(); ++i) load_mtl(tok[i]);
        } else if (is_free_form(key)) {
            lines_.fail(tok[0], fmt::format("free-form geometry ({}) is not supported: lancer reads polygons (f)", excerpt(key)));
        } else if (!is_passed_over(key)) {
            lines_.fail(tok[0], fmt::format("unknown statement {}", excerpt(key)));
        }
    }

    double coordinate(const LineToken& t, const std::string& what) {
        const double x = lines_.number(t, what);
        if (auto problem = coordinate_problem(x)) lines_.fail(t, fmt::format("the {} {}", what, *problem));
        return x;
    }

    // Checks that the `count` numbers after the keyword are coordinates, and that any more are numbers.
    template <int N>
    glm::vec<N, double> coordinates(const std::string& what, std::size_t count) {
        const auto& tok = lines_.tokens();
        glm::vec<N, double> out{0.0};
        for (std::size_t i = 1; i < tok.size(); ++i) {
            if (i <= count)
                out[static_cast<int>(i - 1)] = coordinate(tok[i], what);
            else
                lines_.number(tok[i], "value after the coordinates");
        }
        return out;
    }

    // One index of a corner: 1-based, or negative counting back from the last one defined so far.
    std::uint32_t index(const LineToken& t, std::string_view digits, std::size_t defined, const char* what, const char* whats) {
        const long long i = lines_.integer(t, digits, fmt::format("{} index", what));
        if (i == 0) lines_.fail(t, fmt::format("{} index 0 names nothing: OBJ indices start at 1 (or count back from -1)", what));
        const long long resolved = i > 0 ? i - 1 : static_cast<long long>(defined) + i;
        if (resolved < 0 || resolved >= static_cast<long long>(defined))
            lines_.fail(t, fmt::format("{} index {} is out of range: {} {} defined above this line", what, i, defined,
                                        defined == 1 ? std::string(what) + " is" : std::string(whats) + " are"));
        return static_cast<std::uint32_t>(resolved);
    }

    Corner corner(const LineToken& t) {
        std::string_view parts[3];
        int count = 0;
        std::string_view rest = t.text;
        for (;;) {
            const std::size_t slash = rest.find('/');
            if (count == 3) lines_.fail(t, fmt::format("a face corner is v, v/vt, v//vn or v/vt/vn, not {}", excerpt(t.text)));
            parts[count++] = rest.substr(0, slash);
            if (slash == std::string_view::npos) break;
            rest.remove_prefix(slash + 1);
        }
        if (parts[0].empty() || (count >= 2 && parts[1].empty() && count == 2) || (count == 3 && parts[2].empty()))
            lines_.fail(t, fmt::format("a face corner is v, v/vt, v//vn or v/vt/vn, not {}", excerpt(t.text)));
        Corner c;
        c.v = index(t, parts[0], positions_.size(), "vertex", "vertices");
        if (count >= 2 && !parts[1].empty()) c.vt = index(t, parts[1], uvs_.size(), "texture coordinate", "texture coordinates");
        if (count == 3) c.vn = index(t, parts[2], normals_.size(), "normal", "normals");
        return c;
    }

    // The mesh's vertex for a corner: the same (v, vt, vn) always gives the same vertex.
    std::uint32_t vertex_of(const Corner& c) {
        if (!faces_have_uv_ && !faces_have_normal_) {  // positions only: the file's own numbering
            take_positions_up_to(positions_.size());
            return c.v;
        }
        if (c.v >= first_vertex_of_position_.size()) first_vertex_of_position_.resize(positions_.size(), kNone);
        std::uint32_t& first = first_vertex_of_position_[c.v];
        if (first != kNone && corners_[first] == c) return first;
        if (first != kNone) {
            if (auto it = other_vertices_.find(c); it != other_vertices_.end()) return it->second;
        }
        if (mesh_.positions.size() >= kMaxMeshVertices)
            lines_.fail_at_line(fmt::format("more than {} vertices: lancer's indices are 32-bit", kMaxMeshVertices));
        const auto v = static_cast<std::uint32_t>(mesh_.positions.size());
        mesh_.positions.push_back(positions_[c.v]);
        if (c.vt != kNone) mesh_.uvs.push_back(uvs_[c.vt]);
        if (c.vn != kNone) mesh_.normals.push_back(normals_[c.vn]);
        corners_.push_back(c);
        if (first == kNone)
            first = v;
        else
            other_vertices_.emplace(c, v);
        return v;
    }

    void face() {
        const auto& tok = lines_.tokens();
        if (tok.size() < 4) lines_.fail_after_last(fmt::format("a face needs at least 3 corners, found {}", tok.size() - 1));
        polygon_.clear();
        for (std::size_t i = 1; i < tok.size(); ++i) {
            const Corner c = corner(tok[i]);
            const bool has_uv = c.vt != kNone, has_normal = c.vn != kNone;
            if (first_face_line_ == 0) {
                first_face_line_ = lines_.line();
                faces_have_uv_ = has_uv;
                faces_have_normal_ = has_normal;
            }
            if (has_uv != faces_have_uv_ || has_normal != faces_have_normal_)
                lines_.fail(tok[i], fmt::format("this corner {} texture coordinate and {} normal, but the first face's corners "
                                                "(line {}) {} and {}: all faces must give the same",
                                                has_uv ? "has a" : "has no", has_normal ? "a" : "no", first_face_line_,
                                                faces_have_uv_ ? "have one" : "have none", faces_have_normal_ ? "have one" : "have none"));
            polygon_.push_back(vertex_of(c));
        }
        TriangleFan(mesh_).add_polygon(polygon_, material_);
    }

    void use_material() {
        const auto& tok = lines_.tokens();
        if (tok.size() < 2) lines_.fail_after_last("usemtl needs a material name");
        const std::string name(lines_.rest_from(1));
        for (std::size_t m = 0; m < mesh_.materials.size(); ++m)
            if (mesh_.materials[m].name == name) {
                material_ = static_cast<std::uint32_t>(m);
                any_material_ = true;
                return;
            }
        lines_.fail(tok[1], fmt::format("no material {} in the MTL files named above this line{}", excerpt(name),
                                        mtl_files_ == 0 ? " (there is no mtllib line before it)" : ""));
    }

    void load_mtl(const LineToken& t) {
        const std::string name(t.text);
        const std::string path = resolve_against(companions_.folder, name);
        std::string text;
        try {
            text = companions_.read_mtl(path);
        } catch (const SceneError&) {
            throw;
        } catch (const UserError& e) {
            lines_.fail(t, fmt::format("cannot read the MTL file {} ({}): {}", excerpt(name), path, e.what()));
        }
        read_mtl(text, path, companions_.texture_exists, mesh_.materials);
        mesh_.companion_files.push_back(path);
        ++mtl_files_;
    }

    void take_positions_up_to(std::size_t n) {
        mesh_.positions.insert(mesh_.positions.end(), positions_.begin() + static_cast<std::ptrdiff_t>(mesh_.positions.size()),
                               positions_.begin() + static_cast<std::ptrdiff_t>(n));
    }

    // Faces before the first usemtl of a file that uses materials get one with the MTL defaults.
    void assign_default_material() {
        if (!any_material_) {
            mesh_.triangle_materials.clear();
            return;
        }
        const auto unnamed = static_cast<std::uint32_t>(mesh_.materials.size());
        bool needed = false;
        for (std::uint32_t& m : mesh_.triangle_materials)
            if (m == kNone) {
                m = unnamed;
                needed = true;
            }
        if (needed) mesh_.materials.emplace_back();
    }

    TextLines lines_;
    const ObjCompanions& companions_;
    TriangleMesh mesh_;
    std::vector<glm::dvec3> positions_, normals_;  // as the file lists them
    std::vector<glm::dvec2> uvs_;
    std::vector<std::uint32_t> first_vertex_of_position_;  // the mesh vertex of the first corner with this v
    std::vector<Corner> corners_;                            // per mesh vertex, the corner it came from
    std::unordered_map<Corner, std::uint32_t, CornerHash> other_vertices_;
    std::vector<std::uint32_t> polygon_;
    std::uint32_t material_ = kNone;  // until the first usemtl
    bool any_material_ = false;
    int mtl_files_ = 0;
    int first_face_line_ = 0;
    bool faces_have_uv_ = false, faces_have_normal_ = false;
};

}  // namespace

ObjCompanions companions_on_disk(const std::string& obj_path) {
    ObjCompanions c;
    c.folder = std::filesystem::path(obj_path).parent_path().string();
    c.read_mtl = [](const std::string& path) { return read_mesh_bytes(path); };
    c.texture_exists = [](const std::string& path) {
        std::error_code ec;
        return std::filesystem::is_regular_file(path, ec);
    };
    return c;
}

TriangleMesh read_obj(std::string_view text, const std::string& name_for_messages, const ObjCompanions& companions) {
    return ObjReader(text, name_for_messages, companions).read();
}

TriangleMesh read_obj_file(const std::string& path) { return read_obj(read_mesh_file_bytes(path), path, companions_on_disk(path)); }

}  // namespace lancer::mesh
