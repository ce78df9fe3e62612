#pragma once
// Wavefront MTL: the materials an OBJ file names with mtllib and picks with usemtl. lancer takes
// newmtl, Kd, Ks, Ns, d (or Tr = 1 - d) and map_Kd; every other statement (Ka, Ke, Ni, illum, the
// other maps, PBR extensions) describes what lancer's material model does not have and is passed over.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace lancer::mesh {

// Whether a file exists: a missing texture is an error at the map_Kd line that names it.
using FileExists = std::function<bool(const std::string& path)>;

// The path `name` names, relative to `folder` unless it is absolute.
std::string resolve_against(const std::string& folder, const std::string& name);

// Appends the materials of `text` (the file `mtl_path`, for messages and for resolving map_Kd) to
// `materials`. Throws SceneError at mtl_path:line:column for a bad value, a material defined twice,
// a statement before the first newmtl, or a texture that does not exist.
void read_mtl(std::string_view text, const std::string& mtl_path, const FileExists& texture_exists,
              std::vector<MeshMaterial>& materials);

}  // namespace lancer::mesh
