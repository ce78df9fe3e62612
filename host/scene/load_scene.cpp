#include "scene/load_scene.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "core/file_reading.hpp"
#include "image/adaptive.hpp"
#include "scene/camera.hpp"
#include "scene/limits.hpp"
#include "scene/parse_animation.hpp"
#include "scene/parse_lights.hpp"
#include "scene/parse_material_maps.hpp"
#include "scene/parse_optics.hpp"
#include "scene/parse_shapes.hpp"
#include "scene/placement.hpp"
#include "scene/shape_bounds.hpp"
#include "scene/string_position.hpp"
#include "scene/toml_reader.hpp"
#include "scene/transform.hpp"
#include "surface/expr/program.hpp"

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

void read_camera(TableReader& t, CameraSpec& c) {
    c.eye = t.required_vec3("eye");
    c.look_at = t.required_vec3("look_at");
    c.up = t.vec3("up", c.up);
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
    m.color = check_color(t, "color", t.vec3("color", m.color));
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

using MaterialIndex = std::map<std::string, std::uint32_t, std::less<>>;

// The material an object or group names, or `inherited` (its group's, or the scene's default).
std::uint32_t read_material_reference(TableReader& t, const MaterialIndex& materials, std::uint32_t inherited) {
    if (!t.has("material")) {
        t.accept("material");
        return inherited;
    }
    std::string name = t.string("material", "");
    auto found = materials.find(name);
    if (found == materials.end()) t.fail("material", "unknown material '" + name + "'" + did_you_mean(name, names_of(materials)));
    return found->second;
}

// One shape of an [[object]] entry (or of a group's `objects`), placed by `parent` (its groups'
// transforms) and then its own.
Object read_object(TableReader& t, const std::string& type, const MaterialIndex& materials, std::uint32_t inherited_material,
                   const glm::dmat4& parent) {
    const auto& readers = shape_readers();
    auto reader = readers.find(type);
    if (reader == readers.end()) {
        auto types = names_of(readers);
        types.insert("group");
        t.fail("type", "unknown object type '" + type + "'" + did_you_mean(type, types));
    }
    Object o;
    o.where = t.location();
    const glm::dmat4 to_world = read_transform(t, parent);
    o.shape = reader->second(t, to_world);
    place(o, to_world);
    o.material = read_material_reference(t, materials, inherited_material);
    o.name = t.string("name", "");
    t.finish();
    return o;
}

// The scene-wide limits on surfaces (limits.hpp): parametric and implicit surfaces are counted
// before one is read (reading subdivides or expands it, the expensive part), patches once an
// object's are known.
struct SurfaceTotals {
    int parametric = 0;
    int implicit = 0;
    int operations = 0;
    long long patches = 0;

    void before(TableReader& t, const std::optional<std::string>& type) {
        if (type == "parametric" && ++parametric > limits::kMaxParametricSurfaces)
            t.fail("type", fmt::format("too many parametric surfaces (the limit is {} per scene)",
                                       limits::kMaxParametricSurfaces));
        if (type == "implicit" && ++implicit > limits::kMaxImplicitSurfaces)
            t.fail("type", fmt::format("too many implicit surfaces (the limit is {} per scene)",
                                       limits::kMaxImplicitSurfaces));
    }
    void after(TableReader& t, const Object& o) {
        int added = 0;
        if (const auto* p = std::get_if<ParametricObject>(&o.shape)) {
            const surface::Expr* xyz[] = {&p->surface.x, &p->surface.y, &p->surface.z};
            added = surface::count_operations(surface::compile_program(xyz));
        } else if (const auto* i = std::get_if<ImplicitObject>(&o.shape)) {
            added = surface::count_operations(i->surface.program);
        }
        if (added > 0 && (operations += added) > limits::kMaxSceneSurfaceOperations)
            t.fail("type", fmt::format("the parametric and implicit surfaces' equations take {} operations so far; the "
                                       "limit is {} per scene (all of them are compiled into the GPU's tracer)",
                                       operations, limits::kMaxSceneSurfaceOperations));
        const auto* b = std::get_if<BezierSurface>(&o.shape);
        if (b && (patches += static_cast<long long>(b->patches.size())) > limits::kMaxPatches)
            t.fail("type", fmt::format("too many Bezier patches: {} so far (the limit is {} per scene)", patches,
                                       limits::kMaxPatches));
    }
};

// "object 3 ('sphere')": an object or group in messages.
std::string describe_object(std::string what, const toml::table& t) {
    if (auto type = t["type"].value<std::string>()) what += " ('" + *type + "')";
    return what;
}

// Groups nest at most this deep (each level is a recursion of the reader).
constexpr int kMaxGroupDepth = 64;

// Reads [[object]] entries into the scene's objects, groups flattened: a group (POV-Ray's union)
// places its `objects` by its transform, gives them its material unless they name their own, and
// its name (an animation moves the whole group).
struct ObjectReading {
    const MaterialIndex& materials;
    SurfaceTotals totals;
    Scene& scene;
    const toml::table* declared = nullptr;  // [declare.NAME]: objects declared once, placed by `type = "object"`

    // POV-Ray's object { Name ... }: the object declared as [declare.NAME] that `of` names, read
    // again for this placement (its `transform` after the declared one's; its `material` for the
    // parts without their own).
    int placements = 0;

    TableReader declared_object(TableReader& t) {
        const std::string name = t.required_string("of");
        if (++placements > limits::kMaxPlacements)
            t.fail("of", fmt::format("too many placements of declared objects (the limit is {})", limits::kMaxPlacements));
        const toml::node* node = declared ? declared->get(name) : nullptr;
        if (!node) {
            std::set<std::string, std::less<>> names;
            if (declared)
                for (auto&& [key, value] : *declared) names.emplace(key.str());
            t.fail("of", "no object is declared as '" + name + "'" +
                             did_you_mean(name, names, names.empty() ? " (declare it in a [declare." + name + "] table)" : ""));
        }
        const toml::table* table = node->as_table();
        if (!table) throw SceneError(location_of(*node, t.file()), "declare." + name + " must be a table: an object");
        return TableReader(*table, t.file(), describe_object("declared object '" + name + "'", *table));
    }

    void entry(TableReader& t, std::uint32_t material, const glm::dmat4& parent, int depth, const std::string& group = "") {
        const std::string type = t.required_string("type");
        if (type == "object") {
            if (depth == kMaxGroupDepth) t.fail("of", fmt::format("objects nest at most {} deep (does a declared object place itself?)", kMaxGroupDepth));
            if (depth > 0 && t.has("name"))
                t.fail("name", "a group's member cannot have its own name: an animation moves the whole group, by its name");
            const std::string name = depth > 0 ? group : t.string("name", "");
            const glm::dmat4 to_world = read_transform(t, parent);
            const std::uint32_t own = read_material_reference(t, materials, material);
            TableReader d = declared_object(t);
            t.finish();
            if (d.has("name")) d.fail("name", "a declared object cannot have a name: name each placement (type = \"object\")");
            entry(d, own, to_world, depth + 1, name);
            return;
        }
        if (csg_operators().count(type)) {
            if (depth > 0 && t.has("name"))
                t.fail("name", "a group's member cannot have its own name: an animation moves the whole group, by its name");
            Object o;
            o.where = t.location();
            o.name = depth > 0 ? group : t.string("name", "");
            Csg csg;
            operand(t, csg, material, parent, depth);
            const std::optional<Aabb> box = csg_bounds(csg.leaves, csg.program);
            if (!box)
                t.fail("type", fmt::format("this {} is unbounded (a half-space, or an inverse, reaches to infinity): "
                                           "intersect it with a bounded solid", type));
            if (box->empty())
                t.fail("type", fmt::format("this {} is empty: the boxes of the solids it intersects do not overlap", type));
            csg.lo = box->lo;
            csg.hi = box->hi;
            o.material = csg.leaves.front().material;  // what shadow rays through it see of it
            o.shape = std::move(csg);
            scene.objects.push_back(std::move(o));
            if (scene.objects.size() > static_cast<std::size_t>(limits::kMaxObjects))
                t.fail("type", fmt::format("too many objects with the groups' members (the limit is {})", limits::kMaxObjects));
            return;
        }
        if (type != "group") {
            totals.before(t, type);
            if (depth > 0 && t.has("name"))
                t.fail("name", "a group's member cannot have its own name: an animation moves the whole group, by its name");
            scene.objects.push_back(read_object(t, type, materials, material, parent));
            Object& o = scene.objects.back();
            if (depth > 0) o.name = group;
            totals.after(t, o);
            if (scene.objects.size() > static_cast<std::size_t>(limits::kMaxObjects))
                t.fail("type", fmt::format("too many objects with the groups' members (the limit is {})", limits::kMaxObjects));
            if (auto* b = std::get_if<BezierSurface>(&o.shape); b && !b->source_file.empty())
                scene.dependencies.push_back(b->source_file);
            return;
        }
        if (depth == kMaxGroupDepth) t.fail("type", fmt::format("groups nest at most {} deep", kMaxGroupDepth));
        const glm::dmat4 to_world = read_transform(t, parent);
        const std::uint32_t group_material = read_material_reference(t, materials, material);
        if (depth > 0 && t.has("name"))
            t.fail("name", "a group's member cannot have its own name: an animation moves the whole group, by its name");
        const std::string name = depth > 0 ? group : t.string("name", "");
        const toml::array* members = t.array("objects");
        if (!members || members->empty())
            t.fail(members ? "objects" : "type", "a group needs `objects`: a non-empty list of objects (tables)");
        std::size_t k = 0;
        for (const toml::node& node : *members) {
            const toml::table* member = node.as_table();
            if (!member) throw SceneError(location_of(node, t.file()), "a group's objects must be tables");
            TableReader m(*member, t.file(), describe_object(fmt::format("{} member {}", t.what(), ++k), *member));
            entry(m, group_material, to_world, depth + 1, name);
        }
        t.finish();
    }

    // POV-Ray's CSG words and the operator that joins each operand after the first to the ones
    // before it (inside a CSG object a group is a union, as POV-Ray's is).
    static const std::map<std::string, std::uint32_t, std::less<>>& csg_operators() {
        static const std::map<std::string, std::uint32_t, std::less<>> ops = {
            {"intersection", CSG_AND}, {"difference", CSG_AND_NOT}, {"merge", CSG_OR}};
        return ops;
    }

    // One operand of a CSG object (a solid, or a CSG object or group of them) into `csg`: its
    // leaves and the program that combines them; `inverse = true` takes its outside instead.
    void operand(TableReader& t, Csg& csg, std::uint32_t material, const glm::dmat4& parent, int depth) {
        const std::string type = t.required_string("type");
        const bool inverse = t.boolean("inverse", false);
        if (depth == kMaxGroupDepth) t.fail("type", fmt::format("groups nest at most {} deep", kMaxGroupDepth));
        if (type == "object") {  // a declared object as an operand
            const glm::dmat4 to_world = read_transform(t, parent);
            const std::uint32_t own = read_material_reference(t, materials, material);
            TableReader d = declared_object(t);
            t.finish();
            if (d.has("name")) d.fail("name", "a declared object cannot have a name: name each placement (type = \"object\")");
            operand(d, csg, own, to_world, depth + 1);
            if (inverse) csg.program.push_back(CSG_NOT);
            return;
        }
        auto joined = csg_operators().find(type);
        if (joined != csg_operators().end() || type == "group") {
            const std::uint32_t join = type == "group" ? CSG_OR : joined->second;
            const glm::dmat4 to_world = read_transform(t, parent);
            const std::uint32_t own = read_material_reference(t, materials, material);
            const toml::array* members = t.array("objects");
            if (!members || members->empty())
                t.fail(members ? "objects" : "type", fmt::format("{} needs `objects`: a non-empty list of solids (tables)", type));
            std::size_t k = 0;
            for (const toml::node& node : *members) {
                const toml::table* member = node.as_table();
                if (!member) throw SceneError(location_of(node, t.file()), "a " + type + "'s objects must be tables");
                TableReader m(*member, t.file(), describe_object(fmt::format("{} operand {}", t.what(), k + 1), *member));
                if (m.has("name")) m.fail("name", "a CSG operand cannot have its own name: an animation moves the whole object");
                operand(m, csg, own, to_world, depth + 1);
                if (k++ > 0) csg.program.push_back(join);
            }
            t.finish();
        } else {
            if (csg.leaves.size() == CSG_MAX_LEAVES)
                t.fail("type", fmt::format("a CSG object combines at most {} solids", CSG_MAX_LEAVES));
            Object leaf = read_object(t, type, materials, material, parent);
            const auto* cone = std::get_if<Cone>(&leaf.shape);
            if (!shape_has(shape_type(leaf.shape), SHAPE_SOLID) || (cone && cone->open))
                t.fail(cone ? "open" : "type",
                       fmt::format("{}{} has no inside: CSG combines solids (sphere, box, capped cylinder and cone, plane as "
                                   "the half-space behind its normal) and CSG objects and groups of them",
                                   cone ? "an open " : "a ", type));
            csg.program.push_back(CSG_LEAF | std::uint32_t(csg.leaves.size()) << 4);
            csg.leaves.push_back(std::move(leaf));
        }
        if (inverse) csg.program.push_back(CSG_NOT);
    }
};

// Calls fn(table, index) for each element of an array of tables ([[light]], [[object]]).
template <typename Fn>
void for_each_table(const toml::array& array, const std::string& file, const std::string& what, Fn fn) {
    std::size_t index = 0;
    for (const toml::node& node : array) {
        const toml::table* table = node.as_table();
        if (!table) throw SceneError(location_of(node, file), what + " entries must be tables");
        fn(*table, index++);
    }
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

Scene parse_scene(std::string_view text, const std::string& path) {
    SourceTextScope source(path, text);  // for messages pointing inside strings (expressions)
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw SceneError(location_of(e.source(), path), std::string(e.description()));
    }

    Scene scene;
    scene.path = path;
    TableReader top(root, path, "scene");

    if (const toml::table* t = top.table("render")) {
        TableReader r(*t, path, "[render]");
        read_render(r, scene.render);
    }
    const toml::table* camera = top.table("camera");
    if (!camera) throw SceneError({path, 1, 1}, "the scene has no [camera] table");
    {
        TableReader c(*camera, path, "[camera]");
        read_camera(c, scene.camera);
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

    // Entry i of [[object]] made scene objects [entry_starts[i], entry_starts[i + 1]) (a group, many).
    std::vector<std::size_t> entry_starts{0};
    const toml::table* declared = top.table("declare");
    if (const toml::array* objects = top.array("object")) {
        if (objects->size() > static_cast<std::size_t>(limits::kMaxObjects))
            top.fail("object", "too many objects (the limit is " + std::to_string(limits::kMaxObjects) + ")");
        ObjectReading reading{material_index, {}, scene, declared};
        for_each_table(*objects, path, "[[object]]", [&](const toml::table& t, std::size_t index) {
            TableReader o(t, path, describe_object("object " + std::to_string(index + 1), t));
            reading.entry(o, default_material, glm::dmat4(1.0), 0);
            entry_starts.push_back(scene.objects.size());
        });
    }
    read_animation(top, root, scene, entry_starts);
    top.finish();
    if (scene.photons) check_photon_lights(scene);
    return scene;
}

Scene load_scene(const std::string& path) {
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
    return parse_scene(file.text, path);
}

}  // namespace lancer
