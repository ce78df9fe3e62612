// PLACEHOLDER until the OBJ/PLY readers land (branch mesh-loaders): plain OBJ `v` and `f` only.
#include "mesh/mesh_file.hpp"

#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace lancer {

TriangleMesh read_mesh_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw SceneError({path, 0, 0}, "cannot open");
    TriangleMesh m;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            glm::dvec3 p;
            s >> p.x >> p.y >> p.z;
            m.positions.push_back(p);
        } else if (tag == "f") {
            std::vector<std::uint32_t> f;
            std::string corner;
            while (s >> corner) f.push_back(std::stoul(corner) - 1);
            for (std::size_t k = 2; k < f.size(); ++k) m.triangles.push_back({f[0], f[k - 1], f[k]});
        }
    }
    return m;
}

}  // namespace lancer
