#pragma once
// lancer's documented input limits (README: "Limits"). They are checked while loading, before
// anything is allocated for the values they bound.
namespace lancer::limits {

constexpr int kMaxImageSide = 16384;
constexpr long long kMaxImagePixels = 64LL * 1024 * 1024;  // 64 Mpx: 1 GiB of float RGBA on the host
constexpr int kMaxSamples = 16;                             // 16 x 16 = 256 rays per pixel
constexpr int kMaxDepth = 64;
constexpr int kMaxLights = 256;
constexpr int kMaxAreaLightSamples = 16;                   // 16 x 16 = 256 shadow rays per area light
constexpr int kMaxMaterials = 65536;
constexpr int kMaxObjects = 1 << 20;

}  // namespace lancer::limits
