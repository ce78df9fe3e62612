// [animation]: its keys, defaults and checks, and the references from animations to lights and
// objects. Every value goes through a TableReader, so types are checked, unknown keys are
// reported with a suggestion, and errors point at file:line:col.
#include "scene/parse_animation.hpp"

#include <cmath>
#include <map>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "scene/animation.hpp"
#include "scene/camera.hpp"

namespace lancer {
namespace {

using NameIndex = std::map<std::string, std::size_t, std::less<>>;

// The names of the entries of a top-level array of `root`.
NameIndex index_names(const toml::table& root, std::string_view array_key, std::string_view what,
                      const std::string& file) {
    EntryNames names{std::string(what)};
    if (const toml::array* array = root[array_key].as_array()) names.add(*array, file);
    return names.index();
}

// The value of `key` in `table`, which names an entry of [[light]] or [[object]] by its name
// or (lights only) its 0-based index in the file.
std::size_t resolve_reference(TableReader& t, const toml::table& table, std::string_view key, std::string_view what,
                              std::size_t count, const NameIndex& names, bool allow_index) {
    t.accept(key);
    const toml::node* node = table.get(key);
    if (!node) throw SceneError(t.location(), fmt::format("{}: missing required key '{}'", t.what(), key));
    SourceLocation at = location_of(*node, t.file());
    if (allow_index && node->is_integer()) {
        std::int64_t index = node->as_integer()->get();
        if (index < 0 || static_cast<std::size_t>(index) >= count) {
            std::string range = count == 0   ? fmt::format("the scene has no {}s", what)
                                : count == 1 ? fmt::format("the scene has one {}, number 0", what)
                                             : fmt::format("the scene has {} {}s, 0 to {}", count, what, count - 1);
            throw SceneError(at, fmt::format("{} {} does not exist: {}", what, index, range));
        }
        return static_cast<std::size_t>(index);
    }
    if (!node->is_string())
        throw SceneError(at, allow_index ? fmt::format("{} must be a {}'s name or its 0-based index", key, what)
                                         : fmt::format("{} must be the name of an {}", key, what));
    std::string name = node->as_string()->get();
    auto found = names.find(name);
    if (found == names.end()) {
        std::string hint = names.empty() ? fmt::format(" (give the {} a name = \"{}\")", what, name) : "";
        throw SceneError(at, fmt::format("no {} is named '{}'", what, name) + did_you_mean(name, names_of(names), hint));
    }
    return found->second;
}

Interpolation read_interpolation(TableReader& t) {
    std::string name = t.string("interpolation", "linear");
    if (name == "linear") return Interpolation::Linear;
    if (name == "smooth") return Interpolation::Smooth;
    t.fail("interpolation", "unknown interpolation '" + name + "'" +
                                did_you_mean(name, {"linear", "smooth"}, " (use \"linear\" or \"smooth\")"));
}

// An orbit's keys. The defaults make the orbit pass through `start` (the camera's eye, the
// light's position) at time 0, so frame 0 shows the scene as the file places it.
Orbit read_orbit(TableReader& t, const dvec3& default_center, const dvec3& start, const char* start_name, bool cyclic) {
    Orbit o;
    o.center = t.vec3("center", default_center);
    dvec3 rel = start - o.center;
    double horizontal = std::hypot(rel.x, rel.z);
    if (t.has("radius")) {
        o.radius = t.number("radius", 0.0);
        if (!(o.radius > 0.0)) t.fail("radius", fmt::format("radius must be positive, not {:g}", o.radius));
    } else if (horizontal > 1e-12) {
        o.radius = horizontal;
    } else {
        t.fail("", fmt::format("{}: {} is on the orbit's axis, so radius has no default; give one", t.what(), start_name));
    }
    o.height = t.number("height", rel.y);
    o.start_angle_deg = t.number("start_angle", horizontal > 1e-12 ? std::atan2(rel.z, rel.x) * 180.0 / M_PI : 0.0);
    o.turns = t.number("turns", o.turns);
    if (cyclic && o.turns != std::round(o.turns))
        t.fail("turns", fmt::format("a cyclic animation needs a whole number of turns, not {:g} (the loop would jump)",
                                    o.turns));
    t.finish();
    return o;
}

// `keys = [{ time = 0, PROPERTY = [x, y, z], ... }, ...]`: one Track per property the keys give.
// Every key must give the same properties; times must increase within the clock's range.
std::map<std::string, Track, std::less<>> read_keys(TableReader& t, const std::vector<std::string>& animatable,
                                                    const char* owner, bool cyclic) {
    Interpolation interpolation = read_interpolation(t);
    const toml::array* keys = t.array("keys");
    if (!keys) throw SceneError(t.location(), t.what() + ": missing required key 'keys'");
    if (keys->empty()) t.fail("keys", "keys must hold at least one key, such as { time = 0, " + animatable[0] + " = [0, 0, 0] }");

    std::set<std::string, std::less<>> allowed(animatable.begin(), animatable.end());
    std::string allowed_list = fmt::format("{}", fmt::join(animatable, ", "));
    std::map<std::string, Track, std::less<>> tracks;
    std::set<std::string, std::less<>> first_properties;
    double previous = -1.0;
    for (std::size_t k = 0; k < keys->size(); ++k) {
        const toml::node& node = *keys->get(k);
        const toml::table* key = node.as_table();
        if (!key)
            throw SceneError(location_of(node, t.file()),
                             "each key must be a table such as { time = 0, " + animatable[0] + " = [0, 0, 0] }");
        TableReader kr(*key, t.file(), fmt::format("key {} of {}", k + 1, t.what()));
        double time = kr.required_number("time");
        if (cyclic && !(time >= 0.0 && time < 1.0))
            kr.fail("time", fmt::format("key time must be in [0, 1) in a cyclic animation (time 1 is time 0 again), not {:g}", time));
        if (!(time >= 0.0 && time <= 1.0))
            kr.fail("time", fmt::format("key time must be in [0, 1] (the animation's clock), not {:g}", time));
        if (time <= previous)
            kr.fail("time", fmt::format("key times must increase: {:g} comes after {:g}", time, previous));
        previous = time;

        for (auto&& [name, value] : *key) {
            if (name.str() == "time" || allowed.count(name.str())) continue;
            std::string message = fmt::format("{}: unknown animated property '{}'", kr.what(), name.str()) +
                                  did_you_mean(name.str(), allowed, fmt::format(" ({} animate {})", owner, allowed_list));
            throw SceneError(location_of(name.source(), t.file()), message);
        }
        std::set<std::string, std::less<>> properties;
        for (const std::string& p : animatable) {
            if (!kr.has(p)) continue;
            dvec3 v = kr.vec3(p, dvec3(0.0));
            if (p == "color" && (v.r < 0.0 || v.g < 0.0 || v.b < 0.0)) kr.fail(p, "color components must not be negative");
            properties.insert(p);
            Track& track = tracks[p];
            track.interpolation = interpolation;
            track.times.push_back(time);
            track.values.push_back(v);
        }
        if (properties.empty())
            kr.fail("time", fmt::format("{}: a key must give at least one of {}", kr.what(), allowed_list));
        if (k == 0) {
            first_properties = properties;
        } else if (properties != first_properties) {
            throw SceneError(kr.location(), fmt::format("{}: every key must give the same properties as key 1 ({})",
                                                        kr.what(), fmt::join(first_properties, ", ")));
        }
        kr.finish();
    }
    return tracks;
}

// Each (light or object, property) may be driven by one animation only.
class Claims {
public:
    // `key` is the entry's reference to its light or object, where errors point.
    void claim(TableReader& t, std::string_view key, const std::string& target, const std::string& property) {
        auto [it, fresh] = claims_.emplace(target + " " + property, t.location(key));
        if (!fresh)
            throw SceneError(t.location(key), fmt::format("{}: the {} of {} is already animated at line {}", t.what(),
                                                       property, target, it->second.line));
    }

private:
    std::map<std::string, SourceLocation> claims_;
};

std::string light_label(const Scene& scene, std::size_t i) {
    return scene.lights[i].name.empty() ? fmt::format("light {}", i) : fmt::format("light '{}'", scene.lights[i].name);
}

// Calls fn(reader, table) for each table of the array `key` of `parent`.
template <typename Fn>
void for_each_entry(TableReader& parent, std::string_view key, const std::string& what, Fn fn) {
    const toml::array* array = parent.array(key);
    if (!array) return;
    for (const toml::node& node : *array) {
        const toml::table* table = node.as_table();
        if (!table) throw SceneError(location_of(node, parent.file()), what + " entries must be tables");
        TableReader reader(*table, parent.file(), what);
        fn(reader, *table);
    }
}

}  // namespace

void EntryNames::add(const toml::array& entries, const std::string& file) {
    for (const toml::node& entry : entries) {
        const std::size_t i = count_++;
        const toml::table* table = entry.as_table();
        const toml::node* node = table ? table->get("name") : nullptr;
        if (!node || !node->is_string()) continue;  // the loader has already checked the type
        std::string name = node_string(*node, file, what_ + " name");
        SourceLocation at = location_of(*node, file);
        if (name.empty()) throw SceneError(at, fmt::format("{} name must not be empty", what_));
        if (auto seen = first_line_.find(name); seen != first_line_.end())
            throw SceneError(at, fmt::format("{} name '{}' is already used at line {}", what_, name, seen->second));
        first_line_.emplace(name, at.line);
        index_.emplace(std::move(name), i);
    }
}

void read_animation(TableReader& top, const toml::table& root, Scene& scene, std::span<const std::size_t> entry_starts,
                    const EntryNames* object_entries) {
    const std::string& file = top.file();
    NameIndex light_names = index_names(root, "light", "light", file);
    NameIndex read_here;
    const NameIndex& object_names = object_entries ? object_entries->index() : (read_here = index_names(root, "object", "object", file));
    const toml::table* table = top.table("animation");
    if (!table) return;

    TableReader t(*table, file, "[animation]");
    Animation a;
    if (!t.has("frames")) throw SceneError(t.location(), "[animation]: missing required key 'frames'");
    a.frames = t.integer("frames", 0);
    if (a.frames < 1 || a.frames > kMaxFrames)
        t.fail("frames", fmt::format("frames must be between 1 and {}, not {}", kMaxFrames, a.frames));
    a.fps = t.number("fps", a.fps);
    // ffmpeg takes the rate as a fraction with a denominator of about 10^6 at most: below 0.01
    // fps (a frame every 100 s) an .mp4 loses frames, and 1e-12 is no rate at all. Refused
    // here, before any frame is rendered, not by ffmpeg after all of them.
    if (!(a.fps >= kMinFps && a.fps <= kMaxFps))
        t.fail("fps", fmt::format("fps must be between {:g} and {:g}, not {:g}", kMinFps, kMaxFps, a.fps));
    a.cyclic = t.boolean("cyclic", a.cyclic);

    if (const toml::table* orbit = t.table("camera_orbit")) {
        TableReader o(*orbit, file, "[animation.camera_orbit]");
        a.camera_orbit = read_orbit(o, scene.camera.look_at, scene.camera.eye, "the [camera] eye", a.cyclic);
        const dvec3& up = scene.camera.up;
        if (up.x != 0.0 || up.z != 0.0 || !(up.y > 0.0))
            o.fail("", fmt::format("[animation.camera_orbit] circles the y axis, so [camera] up must be [0, 1, 0], not "
                                   "[{:g}, {:g}, {:g}]",
                                   up.x, up.y, up.z));
        // The camera basis needs the view to lean off the vertical (camera.cpp's 1e-6 bound).
        double lean = a.camera_orbit->radius / std::hypot(a.camera_orbit->radius, a.camera_orbit->height);
        if (lean < 1e-5)
            o.fail("height", "the orbit looks straight down or up (height is too large for the radius)");
        // And the camera must exist all the way round (a radius too small for the eye to leave
        // the look-at point): checked where the frames will be, not first when one is rendered.
        for (double time : {0.0, 0.25, 0.5, 0.75}) {
            CameraSpec camera = scene.camera;
            camera.eye = a.camera_orbit->position_at(time);
            camera.look_at = a.camera_orbit->center;
            try {
                make_camera_basis(camera, 1, 1);
            } catch (const UserError& e) {
                o.fail(o.has("radius") ? "radius" : "", fmt::format("[animation.camera_orbit]: {}", e.what()));
            }
        }
    }

    Claims claims;
    for_each_entry(t, "light_orbit", "[[animation.light_orbit]]", [&](TableReader& r, const toml::table& entry) {
        std::size_t light = resolve_reference(r, entry, "light", "light", scene.lights.size(), light_names, true);
        claims.claim(r, "light", light_label(scene, light), "position");
        a.light_orbits.push_back({light, read_orbit(r, dvec3(0.0), scene.lights[light].position, "the light", a.cyclic)});
    });
    for_each_entry(t, "light", "[[animation.light]]", [&](TableReader& r, const toml::table& entry) {
        std::size_t light = resolve_reference(r, entry, "light", "light", scene.lights.size(), light_names, true);
        auto tracks = read_keys(r, {"position", "color"}, "lights", a.cyclic);
        LightKeys keys{light, {}, {}};
        for (auto& [property, track] : tracks) {
            claims.claim(r, "light", light_label(scene, light), property);
            (property == "position" ? keys.position : keys.color) = std::move(track);
        }
        r.finish();
        a.light_keys.push_back(std::move(keys));
    });
    for_each_entry(t, "object", "[[animation.object]]", [&](TableReader& r, const toml::table& entry) {
        std::size_t index = resolve_reference(r, entry, "object", "object", entry_starts.size() - 1, object_names, false);
        const std::size_t first = entry_starts[index], count = entry_starts[index + 1] - first;  // a group: its members
        auto tracks = read_keys(r, {"translate"}, "objects", a.cyclic);
        claims.claim(r, "object", "object '" + scene.objects[first].name.str() + "'", "translate");
        r.finish();
        a.object_keys.push_back({first, count, std::move(tracks.at("translate"))});
    });
    t.finish();
    scene.animation = std::make_shared<const Animation>(std::move(a));
}

}  // namespace lancer
