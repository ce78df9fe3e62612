#include "scene/parse_material_maps.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "scene/limits.hpp"
#include "scene/transform.hpp"

namespace lancer {
namespace {

// One of a few names, with a suggestion for typos: "unknown wrap 'clmap' (did you mean 'clamp'?)".
template <typename T>
T choose(const toml::node& node, const std::string& file, const std::string& what,
         const std::map<std::string, T, std::less<>>& choices) {
    auto text = node.value<std::string>();
    std::string list;
    for (const auto& [name, value] : choices) list += (list.empty() ? "\"" : ", \"") + name + "\"";
    if (!text) throw SceneError(location_of(node, file), fmt::format("{} must be a string: one of {}", what, list));
    auto found = choices.find(*text);
    if (found != choices.end()) return found->second;
    std::string message = fmt::format("unknown {} '{}'", what, *text) +
                          did_you_mean(*text, names_of(choices), fmt::format(" (expected one of {})", list));
    throw SceneError(location_of(node, file), message);
}

// A number for both components, or [x, y].
glm::dvec2 read_pair(const toml::node& node, const std::string& file, const std::string& what) {
    if (const toml::array* a = node.as_array()) {
        if (a->size() != 2)
            throw SceneError(location_of(node, file), fmt::format("{} must be a number or an array of 2 numbers, not an array of {}",
                                                                  what, a->size()));
        return {node_number(*a->get(0), file, what + "[0]"), node_number(*a->get(1), file, what + "[1]")};
    }
    return glm::dvec2(node_number(node, file, what));
}

const std::map<std::string, TextureWrap, std::less<>> kWraps = {{"repeat", TextureWrap::Repeat},
                                                                 {"clamp", TextureWrap::Clamp}};

void read_wrap(const toml::node& node, const std::string& file, ImageTexture& tex) {
    if (const toml::array* a = node.as_array()) {
        if (a->size() != 2)
            throw SceneError(location_of(node, file), "wrap must be a string or an array of 2 strings ([u, v])");
        tex.wrap_u = choose(*a->get(0), file, "wrap", kWraps);
        tex.wrap_v = choose(*a->get(1), file, "wrap", kWraps);
        return;
    }
    tex.wrap_u = tex.wrap_v = choose(node, file, "wrap", kWraps);
}

ImageTexture read_texture(TableReader& material, TextureLibrary& textures) {
    const toml::node* node = material.node("texture");
    ImageTexture tex;
    const std::string& file = material.file();
    std::string dir = std::filesystem::path(file).parent_path().string();
    auto resolve = [&](const std::string& name) { return (std::filesystem::path(dir) / name).lexically_normal().string(); };
    if (node->is_string()) {
        std::string name = node_string(*node, file, "texture");
        tex.path = resolve(name);
        tex.image = textures.load(material, "texture", name, tex.path);
        return tex;
    }
    const toml::table* table = node->as_table();
    if (!table)
        throw SceneError(location_of(*node, file), "texture must be a file name or a table { file = \"...\", ... }");
    TableReader t(*table, file, "texture of " + material.what());
    std::string name = t.required_string("file");
    tex.path = resolve(name);
    tex.image = textures.load(t, "file", name, tex.path);
    if (const toml::node* s = t.node("scale")) {
        tex.scale = read_pair(*s, file, "scale");
        if (!(tex.scale.x > 0.0 && tex.scale.y > 0.0))
            t.fail("scale", fmt::format("texture scale must be positive, not {:g}", std::min(tex.scale.x, tex.scale.y)));
    }
    if (const toml::node* o = t.node("offset")) tex.offset = read_pair(*o, file, "offset");
    tex.rotate_deg = t.number("rotate", 0.0);
    if (const toml::node* w = t.node("wrap")) read_wrap(*w, file, tex);
    if (const toml::node* f = t.node("filter"))
        tex.filter = choose(*f, file, "filter",
                            std::map<std::string, TextureFilter, std::less<>>{{"bilinear", TextureFilter::Bilinear},
                                                                             {"nearest", TextureFilter::Nearest}});
    t.finish();
    return tex;
}

const std::map<std::string, PatternType, std::less<>> kPatternTypes = {
    {"noise", PatternType::Noise}, {"turbulence", PatternType::Turbulence},
    {"marble", PatternType::Marble}, {"wood", PatternType::Wood}};

// How far turbulence displaces each type by default (noise and turbulence take none).
double default_turbulence(PatternType type) {
    switch (type) {
        case PatternType::Marble: return 1.0;
        case PatternType::Wood: return 0.1;
        default: return 0.0;
    }
}

}  // namespace

Pattern read_pattern_shape(TableReader& t) {
    Pattern p;
    const toml::node* type = t.node("type");
    if (!type) throw SceneError(t.location(), t.what() + ": missing required key 'type'");
    p.type = choose(*type, t.file(), "pattern type", kPatternTypes);
    const std::string type_name = *type->value<std::string>();

    dvec3 scale(1.0);
    if (const toml::node* s = t.node("scale")) {
        scale = s->is_array() ? node_vec3(*s, t.file(), "scale") : dvec3(node_number(*s, t.file(), "scale"));
        if (!(scale.x > 0.0 && scale.y > 0.0 && scale.z > 0.0))
            t.fail("scale", fmt::format("pattern scale must be positive, not {:g}", std::min({scale.x, scale.y, scale.z})));
    }
    glm::dmat4 m(1.0);
    m[0][0] = scale.x;
    m[1][1] = scale.y;
    m[2][2] = scale.z;
    m = rotation_degrees(t.vec3("rotate", dvec3(0.0))) * m;
    dvec3 translate = t.vec3("translate", dvec3(0.0));
    m[3] += glm::dvec4(translate, 0.0);
    p.to_world = m;

    bool sums = p.type != PatternType::Noise;        // turbulence, marble and wood sum octaves
    bool displaced = p.type == PatternType::Marble || p.type == PatternType::Wood;
    for (const char* key : {"octaves", "omega", "lambda"})
        if (!sums && t.has(key)) t.fail(key, fmt::format("{} has no effect on a '{}' pattern (a single octave)", key, type_name));
    if (!displaced && t.has("turbulence"))
        t.fail("turbulence", fmt::format("turbulence has no effect on a '{}' pattern (only marble and wood)", type_name));

    p.turbulence = t.number("turbulence", default_turbulence(p.type));
    if (!(p.turbulence >= 0.0)) t.fail("turbulence", fmt::format("turbulence must not be negative, not {:g}", p.turbulence));
    p.octaves = t.integer("octaves", p.octaves);
    if (p.octaves < 1 || p.octaves > limits::kMaxOctaves)
        t.fail("octaves", fmt::format("octaves must be between 1 and {}, not {}", limits::kMaxOctaves, p.octaves));
    p.omega = t.number("omega", p.omega);
    if (!(p.omega > 0.0 && p.omega <= 1.0)) t.fail("omega", fmt::format("omega must be in (0, 1], not {:g}", p.omega));
    p.lambda = t.number("lambda", p.lambda);
    if (!(p.lambda >= 1.0 && p.lambda <= 16.0)) t.fail("lambda", fmt::format("lambda must be in [1, 16], not {:g}", p.lambda));
    return p;
}


std::vector<ColorStop> read_ramp(TableReader& t) {
    const toml::array* colors = t.array("colors");
    if (!colors) throw SceneError(t.location(), t.what() + ": missing required key 'colors' (the colour ramp)");
    if (colors->size() < 2 || colors->size() > static_cast<std::size_t>(limits::kMaxPatternColors))
        t.fail("colors", fmt::format("a pattern needs 2 to {} colors, not {}", limits::kMaxPatternColors, colors->size()));
    std::vector<ColorStop> ramp;
    for (std::size_t i = 0; i < colors->size(); ++i) {
        std::string what = fmt::format("colors[{}]", i);
        dvec3 c = node_vec3(*colors->get(i), t.file(), what);
        if (c.r < 0.0 || c.g < 0.0 || c.b < 0.0)
            throw SceneError(location_of(*colors->get(i), t.file()), what + " components must not be negative");
        ramp.push_back({double(i) / double(colors->size() - 1), c});
    }
    if (const toml::array* stops = t.array("stops")) {
        if (stops->size() != colors->size())
            t.fail("stops", fmt::format("stops must hold one position per colour ({}), not {}", colors->size(), stops->size()));
        for (std::size_t i = 0; i < stops->size(); ++i) {
            std::string what = fmt::format("stops[{}]", i);
            double s = node_number(*stops->get(i), t.file(), what);
            if (!(s >= 0.0 && s <= 1.0)) throw SceneError(location_of(*stops->get(i), t.file()), what + " must be in [0, 1]");
            if (i > 0 && s < ramp[i - 1].position)
                throw SceneError(location_of(*stops->get(i), t.file()), "stops must not decrease");
            ramp[i].position = s;
        }
    }
    return ramp;
}

std::shared_ptr<const TextureImage> TextureLibrary::load(const TableReader& t, std::string_view key,
                                                        const std::string& name, const std::string& path) {
    if (auto found = images_.find(path); found != images_.end()) return found->second;
    auto fail = [&](const std::string& why) { t.fail(key, fmt::format("cannot read texture '{}': {}", name, why)); };
    if (images_.size() >= static_cast<std::size_t>(limits::kMaxTextures))
        fail(fmt::format("too many textures (the limit is {} files)", limits::kMaxTextures));
    try {
        ImageFile file = read_image_file(
            path, {limits::kMaxTextureSide, static_cast<long long>(limits::kMaxTextureSide) * limits::kMaxTextureSide});
        long long texels = static_cast<long long>(file.size.width) * file.size.height;
        if (texels_ + texels > limits::kMaxTextureTexels)
            fail(fmt::format("the scene's textures would hold {} texels; the limit is {} (128 MiB) in all",
                             texels_ + texels, limits::kMaxTextureTexels));
        auto image = std::make_shared<const TextureImage>(decode_texture_image(file));
        texels_ += texels;
        images_.emplace(path, image);
        dependencies_.push_back(path);
        return image;
    } catch (const SceneError&) {
        throw;
    } catch (const UserError& e) {
        fail(e.what());
    }
    return nullptr;  // not reached: fail() throws
}

void read_material_maps(TableReader& t, Material& m, TextureLibrary& textures) {
    if (t.has("texture")) m.texture = read_texture(t, textures);
    if (const toml::table* table = t.table("pattern")) {
        TableReader p(*table, t.file(), "pattern of " + t.what());
        Pattern pattern = read_pattern_shape(p);
        pattern.colors = read_ramp(p);
        p.finish();
        m.pattern = std::move(pattern);
    }
    if (const toml::table* table = t.table("bump")) {
        TableReader b(*table, t.file(), "bump of " + t.what());
        Bump bump;
        bump.pattern = read_pattern_shape(b);
        bump.amount = b.number("amount", bump.amount);
        b.finish();
        m.bump = std::move(bump);
    }
}

void set_plane_texture_axes(Plane& plane) {
    const dvec3& n = plane.normal;
    // v along the world's up as seen in the plane; a horizontal plane has none, so +z instead.
    dvec3 up = dvec3(0.0, 1.0, 0.0) - n.y * n;
    dvec3 v = glm::length(up) > 1e-6 ? up : dvec3(0.0, 0.0, 1.0) - n.z * n;
    plane.v_axis = glm::normalize(v);
    plane.u_axis = glm::cross(n, plane.v_axis);
}

}  // namespace lancer
