#pragma once
// Wavefront OBJ: v (x y z, an optional w or r g b after them is passed over), vt (u [v [w]]),
// vn, f with corners v, v/vt, v//vn or v/vt/vn (negative indices count back from the last
// vertex defined; 0 is no index), mtllib, usemtl. Polygons are fanned into triangles.
//
// Corners name a position, a texture coordinate and a normal each; lancer's mesh shares one index
// for all three, so every distinct (v, vt, vn) becomes one vertex (in the order of first use;
// positions no face uses are left out). Two corners with the same v copy the same parsed numbers:
// their positions are bit-identical, and edges stay closed. When faces name positions only, the
// mesh's positions are the file's v lines, all of them, in order (vertex k of the file is k - 1).
//
// Strict where a lenient reader would silently guess: an index must name an element defined above
// it; all faces give texture coordinates (or normals) or none do; a normal of zero length, a
// number that is not finite or beyond lancer's range, a material no MTL file defines, an MTL file
// or texture that cannot be found, and free-form geometry (curv, surf...) are errors at
// file:line:column. Lines (l), points (p), groups (g, o, s) and display attributes are passed over.
#include <functional>
#include <string>
#include <string_view>

#include "mesh/mtl_reader.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lancer::mesh {

// Where the files an OBJ names come from: its MTL files and the textures they name.
struct ObjCompanions {
    std::string folder;  // mtllib names are relative to it
    // The MTL file's text; throws UserError with the reason when it cannot be read.
    std::function<std::string(const std::string& path)> read_mtl;
    FileExists texture_exists;
};

// The companions of the OBJ file at `obj_path`, from disk.
ObjCompanions companions_on_disk(const std::string& obj_path);

// `name_for_messages` is the file name in error locations.
TriangleMesh read_obj(std::string_view text, const std::string& name_for_messages, const ObjCompanions& companions);

TriangleMesh read_obj_file(const std::string& path);

}  // namespace lancer::mesh
