#include "scene/pov_ray_words.hpp"

#include <map>

namespace lancer {
namespace {

using Hints = std::map<std::string_view, std::string_view, std::less<>>;

std::string hint(const Hints& hints, std::string_view word) {
    auto found = hints.find(word);
    return found == hints.end() ? "" : " (" + std::string(found->second) + ")";
}

}  // namespace

std::string pov_ray_key_hint(std::string_view key) {
    static const Hints hints = {
        {"phong", "POV-Ray's phong is lancer's specular, and its phong_size is shininess"},
        {"phong_size", "POV-Ray's phong_size is lancer's shininess, with phong as specular"},
        {"location", "POV-Ray's location is lancer's eye in [camera], position in [[light]]"},
        {"angle", "POV-Ray's horizontal camera angle is [camera] angle (or fov, vertical)"},
        {"sky", "POV-Ray's sky is lancer's up"},
        {"right", "the picture's shape is [render]'s width and height"},
        {"direction", "lancer's camera is set by eye, look_at, up and fov"},
        {"filter", "a POV-Ray filter f on colour c is lancer's transmission = [f r, f g, f b]"},
        {"transmit", "POV-Ray's transmit t is lancer's transmission = t"},
        {"fade_distance", "an interior's fade_distance D and fade_color c are lancer's absorption = (1 - c) / D; a "
                          "light takes fade_distance and fade_power as POV-Ray's"},
        {"fade_power", "a medium's fading is lancer's absorption (Beer-Lambert; see \"Porting from POV-Ray\"); a "
                       "light takes fade_distance and fade_power as POV-Ray's"},
        {"fade_color", "POV-Ray's fade_distance D and fade_color c are lancer's absorption = (1 - c) / D"},
        {"fog_type", "POV-Ray's fog_type 1 is [fog] type = \"constant\", 2 is type = \"ground\""},
        {"fog_offset", "POV-Ray's fog_offset is [fog] offset, with type = \"ground\""},
        {"fog_alt", "POV-Ray's fog_alt is [fog] altitude, with type = \"ground\""},
        {"pigment", "a material's colour is its color, checker, texture or pattern"},
        {"finish", "a material's finish is its own keys: ambient, diffuse, specular, shininess, reflection"},
        {"interior", "a material's interior is its ior and absorption"},
        {"texture_map", "a material takes one texture (an image file) and one pattern"},
        {"normal", "a material's bumps are its bump"},
        {"brilliance", "lancer's diffuse term is Lambert's (POV-Ray's brilliance 1)"},
        {"metallic", "a metal is model = \"microfacet\" with a metal"},
        {"max_trace_level", "POV-Ray's max_trace_level n is lancer's [render] max_depth = n - 1"},
        {"assumed_gamma", "lancer shades in linear light and writes sRGB, as POV-Ray's assumed_gamma 1.0"},
        {"ambient_light", "the scene's ambient light is [ambient] color"},
        {"rotate", "lancer's object transforms are transform = [{ rotate = [x, y, z] }, ...], in the order written"},
        {"translate", "lancer's object transforms are transform = [{ translate = [x, y, z] }, ...], in the order written"},
        {"scale", "lancer's object transforms are transform = [{ scale = s }, ...], in the order written"},
        {"matrix", "lancer's object transforms are transform = [{ matrix = [12 numbers] }, ...]"},
        {"spotlight", "a spot light is [[light]] type = \"spot\""},
        {"area_light", "an area light is [[light]] type = \"area\" with edge_u, edge_v and samples"},
        {"point_at", "only a spot light (type = \"spot\") takes point_at"},
        {"sturm", "lancer's roots are exact without it (a lathe's, a sor's, a blob's, a torus's): leave it out"},
    };
    return hint(hints, key);
}

std::string pov_ray_type_hint(std::string_view type) {
    static const Hints hints = {
        {"union", "POV-Ray's union is lancer's group"},
        {"poly", "POV-Ray's poly, quartic and cubic are lancer's implicit surfaces: type = \"implicit\" with its function"},
        {"quartic", "POV-Ray's poly, quartic and cubic are lancer's implicit surfaces: type = \"implicit\" with its function"},
        {"cubic", "POV-Ray's poly, quartic and cubic are lancer's implicit surfaces: type = \"implicit\" with its function"},
        {"quadric", "a quadric is an implicit surface: type = \"implicit\" with its function"},
        {"polynomial", "a polynomial is an implicit surface: type = \"implicit\" with its function"},
        {"isosurface", "POV-Ray's isosurface is lancer's implicit surface, exact: type = \"implicit\""},
        {"bicubic_patch", "POV-Ray's bicubic_patch is lancer's bezier"},
        {"mesh2", "a mesh is type = \"mesh\" with an OBJ or PLY file (bench/toml_to_pov.py writes mesh2 from one)"},
        {"triangle", "triangles come from a mesh file: type = \"mesh\""},
        {"smooth_triangle", "triangles come from a mesh file: type = \"mesh\", smooth = true"},
        {"polygon", "a parallelogram is a rectangle; any other polygon, a mesh file"},
        {"light_source", "lights are [[light]] tables"},
        {"camera", "the camera is the [camera] table"},
    };
    return hint(hints, type);
}

}  // namespace lancer
