#pragma once
// Image textures for the CPU reference: where a hit lies on its object's texture (per-shape
// mappings, docs/scene-format.md "Texture mapping") and the filtered colour of the image there.
// The shader's twin is shaders/texture.glsl.
#include <glm/vec2.hpp>

#include "cpu/tracer.hpp"

namespace lancer::cpu {

// Texture coordinates (u, v) of a hit at point p.
glm::dvec2 texture_uv(const Hit& hit, const dvec3& p);

// The texture's colour (linear RGB) at surface coordinates uv: texels decoded from sRGB, then
// filtered (bilinear or nearest), the image placed by its scale, rotate, offset and wrap.
dvec3 texture_color(const ImageTexture& texture, const glm::dvec2& uv);

}  // namespace lancer::cpu
