// Draws the billiard-ball textures of scenes/billiards.toml: equirectangular images in lancer's
// spherical mapping (docs/scene-format.md, "Texture mapping"): u = 0.5 faces -z, v = 1 is the
// north pole. Every ball is drawn on the sphere itself, texel by texel, so discs stay round and
// digits upright after the image is wrapped around the ball.
//
//   build/make_billiard_textures [DIR]      (default: scenes/textures)
//
// Deterministic: the same build writes the same bytes (tests/unit/billiard_textures_test.cpp).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace {

constexpr int kWidth = 512;
constexpr int kHeight = 256;
constexpr int kSupersample = 4;  // 4 x 4 samples per texel: smooth edges
constexpr double kPi = 3.14159265358979323846;

struct Vec {
    double x, y, z;
};
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

struct Rgb {
    double r, g, b;  // sRGB, 0..255
};

const Rgb kIvory{246, 242, 228};
const Rgb kInk{18, 18, 22};

// Digits as strokes (polylines) in a box 0.6 wide and 1 high, y up.
using Stroke = std::vector<std::pair<double, double>>;

Stroke arc(double cx, double cy, double rx, double ry, double from_deg, double to_deg) {
    Stroke s;
    const int steps = 48;
    for (int i = 0; i <= steps; ++i) {
        double a = (from_deg + (to_deg - from_deg) * i / steps) * kPi / 180.0;
        s.emplace_back(cx + rx * std::cos(a), cy + ry * std::sin(a));
    }
    return s;
}

Stroke join(Stroke a, const Stroke& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

std::vector<Stroke> glyph(char digit) {
    switch (digit) {
        case '0': return {arc(0.3, 0.5, 0.25, 0.43, 0, 360)};
        case '1': return {{{0.12, 0.76}, {0.34, 0.93}, {0.34, 0.07}}};
        case '2': return {join(arc(0.3, 0.7, 0.24, 0.22, 165, -30), {{0.06, 0.07}, {0.56, 0.07}})};
        case '3': return {arc(0.3, 0.72, 0.22, 0.2, 155, -90), arc(0.3, 0.29, 0.25, 0.23, 90, -155)};
        case '4': return {{{0.44, 0.07}, {0.44, 0.93}, {0.04, 0.33}, {0.58, 0.33}}};
        case '5': return {join({{0.52, 0.93}, {0.13, 0.93}, {0.09, 0.54}}, arc(0.3, 0.32, 0.25, 0.26, 125, -150))};
        case '6': return {arc(0.3, 0.3, 0.25, 0.24, 0, 360), arc(0.62, 0.33, 0.57, 0.57, 180, 105)};
        case '7': return {{{0.04, 0.93}, {0.56, 0.93}, {0.2, 0.07}}};
        case '8': return {arc(0.3, 0.73, 0.2, 0.2, 0, 360), arc(0.3, 0.29, 0.25, 0.24, 0, 360)};
        case '9': return {arc(0.3, 0.7, 0.25, 0.24, 0, 360), arc(-0.02, 0.67, 0.57, 0.57, 0, -75)};
    }
    return {};
}

double segment_distance(double px, double py, std::pair<double, double> a, std::pair<double, double> b) {
    double dx = b.first - a.first, dy = b.second - a.second;
    double len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((px - a.first) * dx + (py - a.second) * dy) / len2 : 0.0;
    t = std::fmax(0.0, std::fmin(1.0, t));
    double ex = a.first + t * dx - px, ey = a.second + t * dy - py;
    return std::sqrt(ex * ex + ey * ey);
}

// True when (x, y), in units of the digits' height with (0, 0) at the centre of the number,
// lies on a stroke of `number`.
bool on_number(const std::string& number, double x, double y) {
    const double advance = 0.68, half_width = 0.075;
    double width = 0.6 + advance * double(number.size() - 1);
    double gx = x + width / 2.0, gy = y + 0.5;
    for (std::size_t i = 0; i < number.size(); ++i) {
        double lx = gx - advance * double(i);
        if (lx < -0.2 || lx > 0.8) continue;
        for (const Stroke& s : glyph(number[i]))
            for (std::size_t k = 0; k + 1 < s.size(); ++k)
                if (segment_distance(lx, gy, s[k], s[k + 1]) <= half_width) return true;
    }
    return false;
}

struct Ball {
    std::string file;
    std::string number;  // empty for the cue ball
    Rgb color;
    bool stripe;
};

// The colour of the ball at unit direction d (sphere space).
Rgb ball_color(const Ball& ball, Vec d) {
    if (ball.number.empty()) {
        // The cue ball: ivory with a red dot on each axis (they show how it turns).
        for (Vec axis : {Vec{1, 0, 0}, Vec{-1, 0, 0}, Vec{0, 1, 0}, Vec{0, -1, 0}, Vec{0, 0, 1}, Vec{0, 0, -1}})
            if (dot(d, axis) > std::cos(0.11)) return {200, 28, 32};
        return kIvory;
    }
    Rgb base = ball.stripe && std::abs(d.y) > 0.5 ? kIvory : ball.color;
    // A white disc with the number facing -z, and another facing +z; upright seen from outside.
    const double disc = 0.40;  // angular radius, radians
    for (double side : {-1.0, 1.0}) {
        double c = side * d.z;  // cosine of the angle to the disc's centre
        if (c <= std::cos(disc)) continue;
        // Gnomonic projection onto the plane touching the ball at the disc's centre.
        double x = -side * d.x / c, y = d.y / c;
        double height = ball.number.size() > 1 ? 0.44 : 0.5;  // digits' height, tangent units
        return on_number(ball.number, x / height, y / height) ? kInk : kIvory;
    }
    return base;
}

void write_ball(const Ball& ball, const std::string& dir) {
    std::vector<unsigned char> rgb(std::size_t(kWidth) * kHeight * 3);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            double r = 0, g = 0, b = 0;
            for (int sy = 0; sy < kSupersample; ++sy) {
                for (int sx = 0; sx < kSupersample; ++sx) {
                    double u = (x + (sx + 0.5) / kSupersample) / kWidth;
                    double v = 1.0 - (y + (sy + 0.5) / kSupersample) / kHeight;  // row 0 is the top
                    double longitude = (u - 0.5) * 2.0 * kPi, latitude = (v - 0.5) * kPi;
                    Vec d{std::sin(longitude) * std::cos(latitude), std::sin(latitude),
                          -std::cos(longitude) * std::cos(latitude)};
                    Rgb c = ball_color(ball, d);
                    r += c.r;
                    g += c.g;
                    b += c.b;
                }
            }
            const double n = kSupersample * kSupersample;
            unsigned char* p = &rgb[(std::size_t(y) * kWidth + x) * 3];
            p[0] = static_cast<unsigned char>(std::lround(r / n));
            p[1] = static_cast<unsigned char>(std::lround(g / n));
            p[2] = static_cast<unsigned char>(std::lround(b / n));
        }
    }
    std::string path = dir + "/" + ball.file;
    if (!stbi_write_png(path.c_str(), kWidth, kHeight, 3, rgb.data(), kWidth * 3)) {
        std::fprintf(stderr, "make_billiard_textures: cannot write %s\n", path.c_str());
        std::exit(1);
    }
    std::printf("%s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    std::string dir = argc > 1 ? argv[1] : "scenes/textures";
    const Ball balls[] = {
        {"ball_cue.png", "", kIvory, false},
        {"ball_1.png", "1", {250, 196, 18}, false},
        {"ball_3.png", "3", {206, 32, 30}, false},
        {"ball_8.png", "8", {22, 22, 26}, false},
        {"ball_9.png", "9", {250, 196, 18}, true},
        {"ball_14.png", "14", {18, 118, 58}, true},
    };
    for (const Ball& ball : balls) write_ball(ball, dir);
    return 0;
}
