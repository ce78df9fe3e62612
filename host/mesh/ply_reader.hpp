#pragma once
// PLY (ascii, binary_little_endian, binary_big_endian). From the element `vertex`: x y z, normals
// nx ny nz, texture coordinates u v (or s t, texture_u texture_v, texture_s texture_t), of any
// scalar type; from `face`: the list vertex_indices (or vertex_index) of any integer types, each
// polygon fanned into triangles; from `tristrips`: the list vertex_indices, -1 restarting the
// strip, every odd triangle of a strip turned around so that all keep the strip's winding.
// Everything else (other elements, other properties, lists included) is read past.
//
// The vertex element must come before face and tristrips (indices are checked as they are read).
// Memory follows the bytes in the file, never a count in the header: a binary element that
// cannot fit in the bytes left is refused at once. Errors give line and column in ascii files and
// "byte N" in binary ones, where N is the offset of the value concerned.
#include <string>
#include <string_view>

#include "mesh/triangle_mesh.hpp"

namespace lancer::mesh {

// `name` is the file name in error locations.
TriangleMesh read_ply(std::string_view bytes, const std::string& name);

}  // namespace lancer::mesh
