#pragma once
// The entry points of lancer's fuzz targets, shared by the libFuzzer binaries (tests/fuzz/*_fuzzer.cpp)
// and by the replay test that runs every corpus and crash file in the normal suite.
//
// Each takes arbitrary bytes and feeds them to the product exactly as a user's file would reach
// it. Input that is rejected with a UserError (the product's "bad input" path, a located message)
// is fine; after input is accepted, the result must satisfy the model's invariants (every number
// finite, and so on). Anything else is a bug: another exception (an InvariantBroken included)
// escapes, and the fuzzer reports it as a crash; sanitizer reports, hangs and leaks are found by
// the fuzzer itself.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace lancer {
struct Scene;
struct TriangleMesh;
}

namespace lancer::fuzz {

// A property the product promises about input it accepted does not hold.
class InvariantBroken : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

// Throws InvariantBroken unless `scene` keeps what an accepted scene promises its renderers:
// every number finite, every index valid, a camera basis that exists, boxes for the BVH.
void check_scene_invariants(const Scene& scene, const std::string& when);

// TOML text -> scene model (parse_scene): every object type, patch files relative to scenes/,
// and the [animation] table, evaluated at its first, middle and last frame; then the BVH, the
// GPU's packed buffers (every float finite) and a 3 x 2 pixel render by the CPU reference
// (every pixel finite). First, the plain TOML reader against toml::parse (plain_toml_check.hpp).
void scene_entry(const std::uint8_t* data, std::size_t size);

// An expression, as a parametric surface's x(u, v) -> parsed expression, evaluated at a point,
// over a box, with derivatives, checked over a domain, and emitted as GLSL; and as an implicit
// surface's f(x, y, z) -> parsed, expanded when a polynomial (degree limit), checked over a box,
// emitted as GLSL and intersected with rays by the CPU reference.
void expression_entry(const std::uint8_t* data, std::size_t size);

// A patch file (.bpt or Newell) -> patches, bounded, split and evaluated.
void patch_entry(const std::uint8_t* data, std::size_t size);

// An entry of the on-disk SPIR-V cache (gpu/shaders/spirv_cache), written to a file and looked up
// as cached_specialization and cached_compile look theirs up (read_specialization, read_compiled:
// the same open, bounds, key and checksum checks, and a compile's manifest against a small tree of
// shader files). The first byte chooses: bit 0, a specialisation's entry or a compile's; bit 1,
// the rest is the whole entry, or the rest is sealed first (given the key asked for and a correct
// checksum, so that the checks past the checksum are reached: a compile's manifest; for a compile
// the rest is then a 2-byte manifest length, the manifest and the words). The lookup must return
// a miss or exactly the words the entry holds; a sealed specialisation with words must be a hit.
void cache_file_entry(const std::uint8_t* data, std::size_t size);

// A farm render's part -> read as `lancer combine` reads it (read_exr_bytes: the header checked
// against the limits and the file's size before the pixels are allocated). An accepted part is
// within kMaxReadSide and kMaxReadPixels, no larger than its bytes can hold, and its exposure is
// finite and in range.
void exr_part_entry(const std::uint8_t* data, std::size_t size);

// Throws InvariantBroken unless `mesh` keeps what an accepted mesh promises the scene: triangles,
// every index valid, normals and texture coordinates none or one per position, every number finite
// and within 1e12, normals of unit length, material indices none or one per triangle and valid.
void check_mesh_invariants(const TriangleMesh& mesh);

// An OBJ file -> TriangleMesh (mesh::read_obj). Text after a line "#MTL" is the MTL file every
// mtllib gets (without it, an mtllib is a missing file); a texture exists when its name ends in .png.
void obj_entry(const std::uint8_t* data, std::size_t size);

// A PLY file (any of its three formats) -> TriangleMesh (mesh::read_ply), and -> a sphere set's
// points (mesh::read_sphere_ply), with and without the object's radius: finite spheres of radius
// above 0, colours within their palette.
void ply_entry(const std::uint8_t* data, std::size_t size);

}  // namespace lancer::fuzz
