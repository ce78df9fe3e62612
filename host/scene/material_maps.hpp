#pragma once
// What a material can add to a plain colour: an image texture, a procedural pattern (Perlin
// noise, turbulence, marble, wood) and a bump (the normal tilted by a pattern's gradient).
// docs/scene-format.md ("Textures and patterns") states every rule; both renderers follow it.
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "image/texture_image.hpp"

namespace lancer {

enum class TextureWrap { Repeat, Clamp };
enum class TextureFilter { Bilinear, Nearest };

// An image placed on a surface's texture coordinates (u, v): one copy of the image covers
// [0, scale.x] x [0, scale.y], turned by `rotate_deg` about (0, 0) and moved by `offset`.
// Image (s, t) = (0, 0) is the bottom-left corner of the image, (1, 1) the top-right one.
struct ImageTexture {
    std::shared_ptr<const TextureImage> image;
    std::string path;  // the file, relative to the working directory (messages, watching)
    glm::dvec2 scale{1.0};
    glm::dvec2 offset{0.0};
    double rotate_deg = 0.0;
    TextureWrap wrap_u = TextureWrap::Repeat;
    TextureWrap wrap_v = TextureWrap::Repeat;
    TextureFilter filter = TextureFilter::Bilinear;
};

enum class PatternType { Noise, Turbulence, Marble, Wood };

struct ColorStop {
    double position;  // in [0, 1], ascending along a ramp
    glm::dvec3 color;
};

// A scalar function of the world position, f(p), from Ken Perlin's improved noise. A colour
// pattern maps f through its colour ramp; a bump tilts the normal by f's gradient.
struct Pattern {
    PatternType type = PatternType::Noise;
    glm::dmat4 to_world{1.0};  // pattern space -> world: scale, then rotate, then translate
    double turbulence = 0.0;   // how far turbulence displaces marble and wood
    int octaves = 6;           // terms of the turbulence sum
    double omega = 0.5;        // amplitude factor from one octave to the next
    double lambda = 2.0;       // frequency factor from one octave to the next
    std::vector<ColorStop> colors;  // colour patterns only: 2 to kMaxPatternColors stops
};

struct Bump {
    Pattern pattern;
    double amount = 0.5;  // how far the normal tilts per unit of the pattern's gradient
};

}  // namespace lancer
