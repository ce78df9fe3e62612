#pragma once
// lancer's documented input limits (docs/limits.md). They are checked while loading, before
// anything is allocated for the values they bound.
#include "core/magnitude.hpp"
#include "image/image.hpp"

namespace lancer::limits {

constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 64LL * 1024 * 1024;  // 64 Mpx: 1 GiB of float RGBA on the host
static_assert(kMaxImageSide == kMaxReadSide && kMaxImagePixels == kMaxReadPixels, "read_png reads what lancer writes");
constexpr int kMaxSamples = 16;                             // 16 x 16 = 256 rays per pixel
constexpr int kMaxDepth = 64;
constexpr int kMaxLights = 256;
constexpr int kMaxAreaLightSamples = 16;                   // 16 x 16 = 256 shadow rays per area light
constexpr int kMaxMaterials = 65536;
constexpr int kMaxObjects = 1 << 20;
// Placements of declared objects ([declare.NAME], type = "object"): each copies its declaration,
// and declarations placing others several times multiply, so a kilobyte of scene could otherwise
// ask for a million objects (850 MB) before kMaxObjects stopped it.
constexpr int kMaxPlacements = 1 << 16;
// Whole-scene totals of what single objects are already limited in (a patch file holds at most
// surface::kMaxPatchesPerFile patches; a parametric surface at most 65,536 cells): many objects
// together must not exhaust memory either. Each parametric surface also becomes a function in
// the GPU's shader, compiled when the scene is loaded.
constexpr long long kMaxPatches = 1 << 16;
// Triangles of a scene's mesh files together (each file's once, however often it is placed):
// 96 bytes each on the GPU, with their tree; in float, a triangle's index is exact below 2^24.
constexpr long long kMaxMeshTriangles = 1LL << 24;
// Spheres of a scene's point sets together (each file's once): 16 bytes each on the GPU, with
// their tree; in float, a sphere's index is exact below 2^24.
constexpr long long kMaxSetSpheres = 1LL << 24;
// Components of a scene's blobs together: 32 bytes each on the GPU, with their trees.
constexpr long long kMaxBlobComponents = 1LL << 22;
// Outline pieces of one prism or text object (a text's glyphs are a few dozen each).
constexpr std::size_t kMaxPrismSegments = std::size_t{1} << 20;
// Pairs of a curved lathe's pieces whose boxes overlap, each refined to see whether they meet
// (lathe_crossing.hpp): about a second's work; beyond, the lathe is refused, never a long wait.
constexpr double kMaxLatheCrossingPairs = 5e7;
constexpr int kMaxParametricSurfaces = 32;
constexpr int kMaxImplicitSurfaces = 32;  // each also a function in the shader
// Operations of a parametric surface's equations after simplification, and of all surfaces of a
// scene together (each is compiled into the tracer): the driver's compile time grows with them
// (docs/robustness.md, "Expression cost").
constexpr int kMaxSurfaceOperations = 256;
constexpr int kMaxSceneSurfaceOperations = 512;
constexpr double kMaxWeightRatio = 1e18;  // largest / smallest weight of a rational patch (float on the GPU)
constexpr long long kMaxSceneFileBytes = 128LL << 20;

// Textures: the GPU keeps every texel of every texture in one storage buffer, and Vulkan
// guarantees storage buffers of 2^27 bytes (maxStorageBufferRange), i.e. 2^25 RGBA8 texels.
constexpr int kMaxTextureSide = 8192;
constexpr long long kMaxTextureTexels = 1LL << 25;  // all textures together: 128 MiB
constexpr int kMaxTextures = 1024;                  // distinct image files
constexpr int kMaxPhotonsPerPass = 1 << 22;          // photons shot per pass (each stored a few times)
constexpr int kMaxPhotonPasses = 1 << 20;
constexpr int kMaxPatternColors = 8;                // stops of a pattern's colour ramp
constexpr int kMaxOctaves = 10;                     // terms of a turbulence sum

}  // namespace lancer::limits
