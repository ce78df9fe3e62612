#include "scene/load_scene.hpp"

#include <malloc.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "core/file_reading.hpp"
#include "core/page_release.hpp"
#include "image/adaptive.hpp"
#include "scene/camera.hpp"
#include "scene/limits.hpp"
#include "scene/object_batches.hpp"
#include "scene/parse_animation.hpp"
#include "scene/parse_lights.hpp"
#include "scene/parse_material_maps.hpp"
#include "scene/parse_objects.hpp"
#include "scene/parse_optics.hpp"
#include "scene/parse_shapes.hpp"
#include "scene/plain_toml.hpp"
#include "scene/string_position.hpp"
#include "scene/scene_values.hpp"
#include "scene/transform.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {
namespace {

void read_render(TableReader& t, RenderSettings& r) {
    r.width = check_int_range(t, "width", t.integer("width", r.width), 1, limits::kMaxImageSide);
    r.height = check_int_range(t, "height", t.integer("height", r.height), 1, limits::kMaxImageSide);
    if (static_cast<long long>(r.width) * r.height > limits::kMaxImagePixels)
        t.fail("height", "width x height exceeds the limit of " + std::to_string(limits::kMaxImagePixels) + " pixels");
    r.samples = check_int_range(t, "samples", t.integer("samples", r.samples), 1, limits::kMaxSamples);
    if (t.has("aa_threshold"))
        r.aa_threshold = check_range(t, "aa_threshold", t.number("aa_threshold", 0.0), 0.0, 3.0);
    r.aa_depth = check_int_range(t, "aa_depth", t.integer("aa_depth", r.aa_depth), 1, limits::kMaxSamples - 1);
    r.aa_method = static_cast<AaMethod>(one_of(t, "aa_method", "adaptive anti-aliasing method", {"neighbours", "spread"}, "neighbours"));
    if (auto problem = adaptive_settings_problem(r, t.has("aa_depth"), t.has("aa_method")))
        t.fail(problem->key, problem->message);
    r.max_depth = check_int_range(t, "max_depth", t.integer("max_depth", r.max_depth), 0, limits::kMaxDepth);
    r.background = check_color(t, "background", t.vec3("background", r.background));
    r.tone.exposure = check_range(t, "exposure", t.number("exposure", r.tone.exposure), -kMaxExposureStops, kMaxExposureStops);
    r.tone.tone = static_cast<Tone>(one_of(t, "tone", "tone curve", {"clamp", "reinhard", "aces"}, "clamp"));
    r.tone.assumed_gamma =
        check_range(t, "assumed_gamma", t.number("assumed_gamma", r.tone.assumed_gamma), kMinAssumedGamma, kMaxAssumedGamma);
    t.finish();
}

void read_photons(TableReader& t, PhotonSettings& p) {
    p.count = check_int_range(t, "count", t.integer("count", p.count), 1, limits::kMaxPhotonsPerPass);
    p.passes = check_int_range(t, "passes", t.integer("passes", p.passes), 1, limits::kMaxPhotonPasses);
    p.caustic_radius = t.number("caustic_radius", p.caustic_radius);
    p.global_radius = t.number("global_radius", p.global_radius);
    for (const char* key : {"caustic_radius", "global_radius"}) {
        double r = std::string_view(key) == "caustic_radius" ? p.caustic_radius : p.global_radius;
        if (!(r > 0.0)) t.fail(key, fmt::format("{} must be positive, not {:g}", key, r));
    }
    p.alpha = t.number("alpha", p.alpha);
    if (!(p.alpha > 0.0 && p.alpha < 1.0)) t.fail("alpha", fmt::format("alpha must be in (0, 1), not {:g}", p.alpha));
    p.seed = static_cast<std::uint32_t>(check_int_range(t, "seed", t.integer("seed", 0), 0, 2147483647));
    p.max_bounces = check_int_range(t, "max_bounces", t.integer("max_bounces", p.max_bounces), 1, limits::kMaxDepth);
    t.finish();
}

// `angle` is POV-Ray's horizontal field of view: the vertical one for the scene's own width and
// height (an image of another shape keeps the vertical angle, as `fov` does).
void read_camera(TableReader& t, CameraSpec& c, const RenderSettings& render) {
    c.eye = t.required_vec3("eye");
    c.look_at = t.required_vec3("look_at");
    c.up = t.vec3("up", c.up);
    if (t.has("angle")) {
        if (t.has("fov")) t.fail("angle", "give either fov (vertical, lancer's) or angle (horizontal, POV-Ray's), not both");
        const double angle = t.number("angle", 0.0);
        if (!(angle > 0.0 && angle < 180.0)) t.fail("angle", "angle must be between 0 and 180 degrees (exclusive)");
        const double half = std::tan(angle * M_PI / 360.0) * double(render.height) / double(render.width);
        c.fov_deg = 2.0 * std::atan(half) * 180.0 / M_PI;
    }
    c.fov_deg = t.number("fov", c.fov_deg);
    if (!(c.fov_deg > 0.0 && c.fov_deg < 180.0)) t.fail("fov", "fov must be between 0 and 180 degrees (exclusive)");
    t.finish();
    try {
        make_camera_basis(c, 1, 1);
    } catch (const UserError& e) {
        throw SceneError(t.location(t.has("up") ? "up" : "look_at"), e.what());
    }
}

Material read_material(TableReader& t, const std::string& name, TextureLibrary& textures) {
    Material m;
    m.name = name;
    m.model = static_cast<Model>(one_of(t, "model", "material model", {"phong", "microfacet"}, "phong"));
    if (m.microfacet()) {
        read_microfacet(t, m);
        t.finish();
        return m;
    }
    // Any sign: a negative component is POV-Ray's "negative light", which subtracts the ambient
    // and diffuse light from what the highlight and reflection add (advanced/sombrero.pov).
    m.color = t.vec3("color", m.color);
    if (const toml::table* checker = t.table("checker")) {
        TableReader c(*checker, t.file(), "checker of material '" + name + "'");
        Checker k;
        const toml::array* colors = c.array("colors");
        if (!colors) c.fail("colors", "checker needs colors = [[r,g,b], [r,g,b]]");
        if (colors->size() != 2) c.fail("colors", "checker colors must hold exactly 2 colours");
        k.color_a = node_vec3(*colors->get(0), t.file(), "colors[0]");
        k.color_b = node_vec3(*colors->get(1), t.file(), "colors[1]");
        check_color(c, "colors", k.color_a);
        check_color(c, "colors", k.color_b);
        k.size = c.number("size", k.size);
        if (!(k.size > 0.0)) c.fail("size", "checker size must be positive");
        if (c.has("transform")) k.to_checker = glm::inverse(read_transform(c));
        c.finish();
        m.checker = k;
    }
    m.ambient = check_range(t, "ambient", t.number("ambient", m.ambient), 0.0, 1e6);
    m.diffuse = check_range(t, "diffuse", t.number("diffuse", m.diffuse), 0.0, 1e6);
    m.specular = check_range(t, "specular", t.number("specular", m.specular), 0.0, 1e6);
    m.shininess = t.number("shininess", m.shininess);
    if (!(m.shininess > 0.0)) t.fail("shininess", "shininess must be positive");
    m.reflection = check_range(t, "reflection", t.number("reflection", m.reflection), 0.0, 1.0);
    read_material_maps(t, m, textures);
    read_optics(t, m);
    t.finish();
    return m;
}

}  // namespace

std::optional<SettingProblem> adaptive_settings_problem(const RenderSettings& r, bool depth_given, bool method_given) {
    if (!r.aa_threshold) {
        if (depth_given) return SettingProblem{"aa_depth", "aa_depth needs aa_threshold: without a threshold every pixel gets the full grid"};
        if (method_given) return SettingProblem{"aa_method", "aa_method needs aa_threshold: without a threshold every pixel gets the full grid"};
        return std::nullopt;
    }
    const std::vector<int> grids = aa_grid_levels(r.samples, r.aa_depth);
    if (r.aa_depth > int(grids.size()) - 1 && r.samples > 1)
        return SettingProblem{"aa_depth", fmt::format("aa_depth {}: samples {} has grids for at most {} refinement{}, each "
                                                      "finer than the last; raise samples or lower aa_depth",
                                                      r.aa_depth, r.samples, max_aa_depth(r.samples),
                                                      max_aa_depth(r.samples) == 1 ? "" : "s")};
    if (r.aa_method == AaMethod::Spread && r.aa_depth < 2)
        return SettingProblem{"aa_method", "aa_method = \"spread\" needs aa_depth of at least 2: a pixel's first ray has "
                                           "no spread, so its first refinement is chosen by its neighbours alone"};
    return std::nullopt;
}

PhotonSettings photon_defaults(const CameraSpec& camera) {
    // The radii are fractions of the distance the camera looks at, a scale of the picture: the
    // caustic map is gathered finer than the smooth indirect light.
    const double view = glm::length(camera.look_at - camera.eye);
    PhotonSettings p;
    p.caustic_radius = 0.005 * view;
    p.global_radius = 0.02 * view;
    return p;
}

namespace {

// Objects per batch of a scene read in batches: a few MiB of TOML tree each.
constexpr std::size_t kObjectsPerBatch = 4096;

// Reads the [[object]] entries (from the root's array, or in batches) with `entries`; the
// entries' names where it checked them itself (EntryNames), else nullptr.
using ObjectsReading = std::function<const EntryNames*(TableReader& top, ObjectEntries& entries)>;

// The scene from its root table, its objects read by `read_entries`.
Scene read_scene(const toml::table& root, const std::string& path, SceneValues& values, const ObjectsReading& read_entries) {
    Scene scene;
    scene.path = path;
    TableReader top(root, path, "scene");
    if (const toml::table* defines = top.table("define")) values.read_defines(*defines, path);

    if (const toml::table* t = top.table("render")) {
        TableReader r(*t, path, "[render]");
        read_render(r, scene.render);
    }
    const toml::table* camera = top.table("camera");
    if (!camera) throw SceneError({path, 1, 1}, "the scene has no [camera] table");
    {
        TableReader c(*camera, path, "[camera]");
        read_camera(c, scene.camera, scene.render);
    }
    if (const toml::table* t = top.table("ambient")) {
        TableReader a(*t, path, "[ambient]");
        scene.ambient = check_color(a, "color", a.vec3("color", scene.ambient));
        a.finish();
    }
    if (const toml::table* t = top.table("photons")) {
        TableReader p(*t, path, "[photons]");
        scene.photons = photon_defaults(scene.camera);
        read_photons(p, *scene.photons);
    }
    if (const toml::array* lights = top.array("light")) {
        if (lights->size() > static_cast<std::size_t>(limits::kMaxLights))
            top.fail("light", "too many lights (the limit is " + std::to_string(limits::kMaxLights) + ")");
        for_each_table(*lights, path, "[[light]]", [&](const toml::table& t, std::size_t) {
            TableReader l(t, path, "[[light]]");
            scene.lights.push_back(read_light(l));
        });
    }

    if (const toml::table* f = top.table("fog")) {
        TableReader t(*f, path, "[fog]");
        Fog fog;
        fog.distance = t.required_number("distance");
        if (!(fog.distance > 0.0)) t.fail("distance", fmt::format("fog distance must be positive, not {:g}", fog.distance));
        fog.color = check_color(t, "color", t.vec3("color", fog.color));
        const std::size_t type = one_of(t, "type", "fog type", {"constant", "ground"}, "constant");
        if (type == 1) {
            Fog::Ground g;
            g.offset = t.number("offset", 0.0);
            g.altitude = t.number("altitude", 1.0);
            if (!(g.altitude > 0.0)) t.fail("altitude", fmt::format("fog altitude must be positive, not {:g}", g.altitude));
            const dvec3 up = t.vec3("up", g.up);
            if (!(glm::length(up) > 0.0)) t.fail("up", "fog up must not be the zero vector");
            g.up = glm::normalize(up);
            fog.ground = g;
        } else {
            for (const char* key : {"offset", "altitude", "up"})
                if (t.has(key)) t.fail(key, fmt::format("{} belongs to the ground fog: type = \"ground\"", key));
        }
        t.finish();
        scene.fog = fog;
    }

    if (const toml::table* s = top.table("sky")) {
        TableReader t(*s, path, "[sky]");
        scene.sky = Sky{read_ramp(t), std::nullopt};
        if (const toml::table* p = t.table("pattern")) {
            TableReader pattern(*p, path, "[sky] pattern");
            scene.sky->pattern = read_pattern_shape(pattern);
            scene.sky->pattern->colors = scene.sky->colors;
            pattern.finish();
        }
        t.finish();
    }

    std::map<std::string, std::uint32_t, std::less<>> material_index;
    TextureLibrary textures(scene.dependencies);
    if (const toml::table* materials = top.table("material")) {
        if (materials->size() > static_cast<std::size_t>(limits::kMaxMaterials))
            top.fail("material", "too many materials (the limit is " + std::to_string(limits::kMaxMaterials) + ")");
        for (auto&& [key, node] : *materials) {
            const toml::table* t = node.as_table();
            std::string name(key.str());
            if (!t) throw SceneError(location_of(node, path), "material '" + name + "' must be a table ([material." + name + "])");
            TableReader m(*t, path, "material '" + name + "'");
            material_index[name] = static_cast<std::uint32_t>(scene.materials.size());
            scene.materials.push_back(read_material(m, name, textures));
        }
    }
    // Objects without `material` use POV-Ray's defaults in white, unless the scene defines "default".
    std::uint32_t default_material;
    if (auto found = material_index.find("default"); found != material_index.end()) {
        default_material = found->second;
    } else {
        default_material = static_cast<std::uint32_t>(scene.materials.size());
        scene.materials.push_back(Material{"default"});
    }

    const MaterialReader read_inline = [&](TableReader& m, const std::string& name) { return read_material(m, name, textures); };
    ObjectEntries entries(top, material_index, read_inline, default_material, scene, textures);
    const EntryNames* object_names = read_entries(top, entries);
    read_animation(top, root, scene, entries.starts(), object_names);
    top.finish();
    if (scene.photons) {
        check_photon_lights(scene);
        for (const Material& m : scene.materials)
            if (m.color.r < 0.0 || m.color.g < 0.0 || m.color.b < 0.0)
                top.fail("photons", fmt::format("material '{}' has a negative colour (POV-Ray's negative light), which a photon "
                                                "cannot carry: photon mapping needs colours of 0 or more",
                                                m.name));
    }
    scene.depends_on_time = values.uses_time();
    return scene;
}

Scene parse_whole(std::string_view text, const std::string& path, SceneTime time) {
    SceneValues values(time);
    SceneValuesScope values_scope(values);
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw SceneError(location_of(e.source(), path), std::string(e.description()));
    }
    return read_scene(root, path, values, [](TableReader& top, ObjectEntries& entries) -> const EntryNames* {
        const toml::array* objects = top.array("object");
        if (!objects) return nullptr;
        if (objects->size() > static_cast<std::size_t>(limits::kMaxObjects))
            top.fail("object", "too many objects (the limit is " + std::to_string(limits::kMaxObjects) + ")");
        entries.read(*objects, top.file());
        return nullptr;
    });
}

// Batches parsed ahead of the one being read, each on a thread of its own: toml::parse takes about
// twice as long as reading, so two keep a second core busy while the first reads (the plain reader
// takes less than the reading: for it, the second costs only a batch's tree).
constexpr std::size_t kParsesAhead = 2;

// Called after each batch is read, with the offset where its text ends: nothing before it is
// read again (load_scene gives those pages back to the kernel).
using TextRead = std::function<void(std::size_t end)>;

// Calls read(tree, batch) for each batch in order, its TOML tree parsed on another thread: by the
// plain reader where the batch is plain TOML (the same tree, faster), by toml::parse otherwise.
template <class Read>
void for_each_batch(std::string_view text, const SceneTextParts& parts, const std::string& path, Read read,
                    const TextRead& text_read) {
    const auto parse = [&](std::size_t i) {
        const ObjectBatch& b = parts.batches[i];
        const std::string_view batch = text.substr(b.begin, b.end - b.begin);
        if (std::optional<toml::table> plain = parse_plain_toml(batch, path)) return std::move(*plain);
        return toml::parse(batch, std::string_view(path));
    };
    std::deque<std::future<toml::table>> ahead;
    std::size_t launched = 0;
    // A scene of one batch (most) is parsed where it is read: no thread at start-up.
    const auto policy = parts.batches.size() > 1 ? std::launch::async : std::launch::deferred;
    const auto launch = [&] { ahead.push_back(std::async(policy, parse, launched++)); };
    while (launched < parts.batches.size() && ahead.size() < kParsesAhead) launch();
    for (std::size_t i = 0; i < parts.batches.size(); ++i) {
        toml::table tree = ahead.front().get();
        ahead.pop_front();
        if (launched < parts.batches.size()) launch();
        read(tree, parts.batches[i]);
        // The batches parsed ahead lie after this one: its text is done with.
        if (text_read) text_read(parts.batches[i].end);
    }
}

Scene read_batches(std::string_view text, const SceneTextParts& parts, const std::string& path, SceneTime time,
                   const TextRead& text_read) {
    if (parts.objects > static_cast<std::size_t>(limits::kMaxObjects))
        throw UserError("too many objects (the limit is " + std::to_string(limits::kMaxObjects) + ")");
    SceneValues values(time);
    SceneValuesScope values_scope(values);
    const toml::table head = toml::parse(std::string_view(parts.head), std::string_view(path));
    EntryNames names("object");
    Scene scene = read_scene(head, path, values, [&](TableReader& top, ObjectEntries& entries) -> const EntryNames* {
        entries.reserve(parts.objects);
        for_each_batch(text, parts, path, [&](const toml::table& tree, const ObjectBatch& batch) {
            const FilePartScope part(tree, batch.first_line);
            const toml::array& objects = *tree.get_as<toml::array>("object");
            entries.read(objects, top.file());  // one name shared by every object's location
            names.add(objects, path);
        }, text_read);
        return &names;
    });
    // The batches' trees were freed in the parsing threads' malloc arenas, whose free pages the
    // kernel gets back only when asked: asked here, before the renderers make their arrays.
    ::malloc_trim(0);
    return scene;
}

// The scene read in batches, or nullopt where the text cannot be split or an error was found
// (the whole parse then reports its first error, where it is).
std::optional<Scene> try_batches(std::string_view text, const std::string& path, SceneTime time, const TextRead& text_read) {
    const std::optional<SceneTextParts> parts = split_object_tables(text, kObjectsPerBatch);
    if (!parts) return std::nullopt;
    try {
        return read_batches(text, *parts, path, time, text_read);
    } catch (const UserError&) {
    } catch (const toml::parse_error&) {
    }
    return std::nullopt;
}

std::string read_scene_text(const std::string& path) {
    // In pieces, stopping past the limit: /dev/zero or an endless pipe is an error, not a hang.
    FileText file;
    try {
        file = read_file(path, static_cast<std::size_t>(limits::kMaxSceneFileBytes));
    } catch (const UserError& e) {
        throw UserError("cannot read scene file '" + path + "': " + e.what());
    }
    if (!file.complete)
        throw UserError(fmt::format("cannot read scene file '{}': it is larger than the limit of {} MiB", path,
                                    limits::kMaxSceneFileBytes >> 20));
    return std::move(file.text);
}

}  // namespace

Scene parse_scene_batches(std::string_view text, const SceneTextParts& parts, const std::string& path, SceneTime time) {
    return read_batches(text, parts, path, time, {});
}

Scene parse_scene(std::string_view text, const std::string& path, SceneTime time, TomlReading reading) {
    SourceTextScope source(path, text);  // for messages pointing inside strings (expressions)
    if (reading == TomlReading::Batches)
        if (std::optional<Scene> scene = try_batches(text, path, time, {})) return std::move(*scene);
    return parse_whole(text, path, time);
}

Scene load_scene(const std::string& path, SceneTime time) {
    std::string text = read_scene_text(path);
    // A million objects' text is as large as their objects: each batch's pages go back to the
    // kernel once it is read, so that the two never coexist whole (docs/performance.md).
    const char* const start = text.data();
    const void* released = start;
    std::optional<Scene> scene;
    {
        SourceTextScope source(path, text);
        scene = try_batches(text, path, time, [&](std::size_t end) { released = release_pages(released, start + end); });
    }
    if (scene) return std::move(*scene);
    // The whole parse finds the error again; where pages were given back, in the file read again.
    if (released != start) text = read_scene_text(path);
    SourceTextScope source(path, text);
    return parse_whole(text, path, time);
}

}  // namespace lancer
