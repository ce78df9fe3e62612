#include "scene/parse_objects.hpp"

#include <map>
#include <set>

#include <fmt/format.h>
#include <glm/mat4x4.hpp>

#include "mesh/mesh_solid.hpp"
#include "scene/limits.hpp"
#include "scene/mesh_materials.hpp"
#include "scene/parse_shapes.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/placement.hpp"
#include "scene/repeat.hpp"
#include "scene/scene_values.hpp"
#include "scene/pov_ray_words.hpp"
#include "scene/shape_bounds.hpp"
#include "scene/transform.hpp"
#include "surface/expr/program.hpp"

namespace lancer {
namespace {

// The material an object or group names, or `inherited` (its group's, or the scene's default).
// A material given inline (a table: POV-Ray's texture { } on the object) is added to the
// scene's, one per table read (a repeat's copies each get theirs, so their colours may differ).
std::uint32_t read_material_reference(TableReader& t, const MaterialChoice& materials, std::uint32_t inherited) {
    if (!t.has("material")) {
        t.accept("material");
        return inherited;
    }
    if (const toml::table* own = t.node("material")->as_table()) {
        if (materials.scene.materials.size() >= static_cast<std::size_t>(limits::kMaxMaterials))
            t.fail("material", fmt::format("too many materials with the objects' own (the limit is {})", limits::kMaxMaterials));
        const SourceLocation at = t.location("material");
        TableReader m(*own, t.file(), t.what() + "'s material");
        materials.scene.materials.push_back(materials.read_inline(m, fmt::format("{}:{}:{}", at.file.str(), at.line, at.column)));
        return static_cast<std::uint32_t>(materials.scene.materials.size() - 1);
    }
    std::string name = t.string("material", "");
    auto found = materials.named.find(name);
    if (found == materials.named.end())
        t.fail("material", "unknown material '" + name + "'" + did_you_mean(name, names_of(materials.named)));
    return found->second;
}

// One shape of an [[object]] entry (or of a group's `objects`), placed by `parent` (its groups'
// transforms) and then its own.
Object read_object(TableReader& t, const std::string& type, const MaterialChoice& materials, std::uint32_t inherited_material,
                   const glm::dmat4& parent) {
    const auto& readers = shape_readers();
    auto reader = readers.find(type);
    if (reader == readers.end()) {
        auto types = names_of(readers);
        types.insert("group");
        std::string suggestion = pov_ray_type_hint(type);  // a POV-Ray word's lancer name says more than a close spelling
        t.fail("type", "unknown object type '" + type + "'" + (suggestion.empty() ? did_you_mean(type, types) : suggestion));
    }
    Object o;
    o.where = t.location();
    const glm::dmat4 to_world = type == "text" ? read_transform(t, parent) * text_frame() : read_transform(t, parent);
    o.shape = reader->second(t, to_world);
    place(o, to_world);
    o.material = read_material_reference(t, materials, inherited_material);
    o.name = t.string("name", "");
    t.finish();
    return o;
}

}  // namespace

// The scene-wide limits on surfaces (limits.hpp): parametric and implicit surfaces are counted
// before one is read (reading subdivides or expands it, the expensive part), patches once an
// object's are known.
struct SurfaceTotals {
    int parametric = 0;
    int implicit = 0;
    int operations = 0;
    long long patches = 0;
    long long triangles = 0;
    long long set_spheres = 0;
    long long blob_components = 0;
    std::set<const MeshGeometry*> meshes;  // counted once however often placed
    std::set<const SphereCloud*> clouds;

    void before(TableReader& t, const std::optional<std::string>& type) {
        if (type == "parametric" && ++parametric > limits::kMaxParametricSurfaces)
            t.fail("type", fmt::format("too many parametric surfaces (the limit is {} per scene)",
                                       limits::kMaxParametricSurfaces));
        if (type && is_implicit_type(*type) && ++implicit > limits::kMaxImplicitSurfaces)
            t.fail("type", fmt::format("too many implicit surfaces (the limit is {} per scene)",
                                       limits::kMaxImplicitSurfaces));
    }
    void after(TableReader& t, const Object& o) {
        int added = 0;
        if (const auto* p = std::get_if<ParametricObject>(&o.shape)) {
            const surface::Expr* xyz[] = {&p->surface->x, &p->surface->y, &p->surface->z};
            added = surface::count_operations(surface::compile_program(xyz));
        } else if (const auto* i = std::get_if<ImplicitObject>(&o.shape)) {
            added = surface::count_operations(i->surface->program);
        }
        if (added > 0 && (operations += added) > limits::kMaxSceneSurfaceOperations)
            t.fail("type", fmt::format("the parametric and implicit surfaces' equations take {} operations so far; the "
                                       "limit is {} per scene (all of them are compiled into the GPU's tracer)",
                                       operations, limits::kMaxSceneSurfaceOperations));
        const auto* mesh = std::get_if<Mesh>(&o.shape);
        if (mesh && meshes.insert(mesh->geometry.get()).second &&
            (triangles += static_cast<long long>(mesh->geometry->mesh().triangles.size())) > limits::kMaxMeshTriangles)
            t.fail("file", fmt::format("too many mesh triangles: {} so far in the scene's mesh files (the limit is {})",
                                       triangles, limits::kMaxMeshTriangles));
        const auto* set = std::get_if<SphereSet>(&o.shape);
        if (set && clouds.insert(set->cloud.get()).second &&
            (set_spheres += static_cast<long long>(set->cloud->spheres().size())) > limits::kMaxSetSpheres)
            t.fail("file", fmt::format("too many spheres in sphere sets: {} so far in the scene's point sets (the limit is {})",
                                       set_spheres, limits::kMaxSetSpheres));
        const auto* blob = std::get_if<Blob>(&o.shape);
        if (blob && (blob_components += static_cast<long long>(blob->components.size())) > limits::kMaxBlobComponents)
            t.fail("type", fmt::format("too many blob components: {} so far in the scene (the limit is {})", blob_components,
                                       limits::kMaxBlobComponents));
        const auto* b = std::get_if<BezierSurface>(&o.shape);
        if (b && (patches += static_cast<long long>(b->patches.size())) > limits::kMaxPatches)
            t.fail("type", fmt::format("too many Bezier patches: {} so far (the limit is {} per scene)", patches,
                                       limits::kMaxPatches));
    }
};

namespace {

// "object 3 ('sphere')": an object or group in messages.
std::string describe_object(std::string what, const toml::table& t) {
    if (auto type = t["type"].value<std::string>()) what += " ('" + *type + "')";
    return what;
}

// Groups nest at most this deep (each level is a recursion of the reader).
constexpr int kMaxGroupDepth = 64;

}  // namespace

// Reads [[object]] entries into the scene's objects, groups flattened: a group (POV-Ray's union)
// places its `objects` by its transform, gives them its material unless they name their own, and
// its name (an animation moves the whole group).
struct ObjectEntries::Reading {
    const MaterialChoice& materials;
    SurfaceTotals totals;
    Scene& scene;
    TextureLibrary& textures;
    std::uint32_t default_material;
    const toml::table* declared = nullptr;
    std::map<const MeshGeometry*, std::vector<std::uint32_t>> mesh_materials;  // each file's, added once
    // A point set's colours as materials, for each material its objects have (added once).
    std::map<std::pair<const SphereCloud*, std::uint32_t>, std::vector<std::uint32_t>> set_materials;
    std::set<std::string> mesh_files;  // in scene.dependencies once, however often placed

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

    // POV-Ray's #for (scene/repeat.hpp): each copy is a placement, so that a few nested lines
    // cannot make a million objects.
    void entry(TableReader& t, std::uint32_t material, const glm::dmat4& parent, int depth, const std::string& group = "") {
        read_repeated(
            t,
            [&](double copies, const auto& fail) {
                if (copies + placements > limits::kMaxPlacements)
                    fail(fmt::format("beyond the {} copies and placements a scene may make ({} so far)", limits::kMaxPlacements,
                                     placements));
                placements += static_cast<int>(copies);
            },
            [&](TableReader& copy) { entry_with_defines(copy, material, parent, depth, group); });
    }

    // POV-Ray's #declare inside a loop: `define = { y = "sin(i)" }` names values for this
    // object's (and its members') numbers, read again for each copy of a repeat.
    void entry_with_defines(TableReader& t, std::uint32_t material, const glm::dmat4& parent, int depth, const std::string& group) {
        const toml::table* own = t.table("define");
        if (!own) return entry_once(t, material, parent, depth, group);
        SceneValues& values = *current_scene_values();
        const std::vector<std::string> names = values.read_defines(*own, t.file(), t.what() + " define");
        entry_once(t, material, parent, depth, group);
        for (const std::string& name : names) values.unbind(name);
    }

    void entry_once(TableReader& t, std::uint32_t material, const glm::dmat4& parent, int depth, const std::string& group) {
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
            // A mesh with materials of its own and none from the scene takes its file's.
            if (auto* mesh = std::get_if<Mesh>(&o.shape);
                mesh && o.material == default_material && !mesh->geometry->mesh().triangle_materials.empty()) {
                auto [found, added] = mesh_materials.try_emplace(mesh->geometry.get());
                if (added) found->second = add_mesh_materials(*mesh->geometry, t, scene, textures);
                mesh->part_materials = found->second;
            }
            if (auto* set = std::get_if<SphereSet>(&o.shape); set && !set->cloud->palette().empty()) {
                auto [found, added] = set_materials.try_emplace({set->cloud.get(), o.material});
                if (added) found->second = add_point_colors(*set->cloud, o.material, t, scene);
                set->part_materials = found->second;
            }
            if (depth > 0) o.name = group;
            totals.after(t, o);
            if (scene.objects.size() > static_cast<std::size_t>(limits::kMaxObjects))
                t.fail("type", fmt::format("too many objects with the groups' members (the limit is {})", limits::kMaxObjects));
            if (auto* b = std::get_if<BezierSurface>(&o.shape); b && !b->source_file.empty())
                scene.dependencies.push_back(b->source_file);
            // A mesh's files too, its MTL files with it (watch reloads them; the render stamp's
            // hash covers them).
            if (auto* m = std::get_if<Mesh>(&o.shape); m && mesh_files.insert(m->source_file).second) {
                scene.dependencies.push_back(m->source_file);
                for (const std::string& file : m->geometry->mesh().companion_files) scene.dependencies.push_back(file);
            }
            if (auto* s = std::get_if<SphereSet>(&o.shape); s && mesh_files.insert(s->source_file).second)
                scene.dependencies.push_back(s->source_file);
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
            totals.before(t, type);
            Object leaf = read_object(t, type, materials, material, parent);
            totals.after(t, leaf);
            const auto* cone = std::get_if<Cone>(&leaf.shape);
            const std::uint32_t kind = shape_type(leaf.shape);
            if (auto* mesh = std::get_if<Mesh>(&leaf.shape)) {
                try {
                    mesh->outward = mesh::outward_side(mesh->geometry->mesh());
                } catch (const UserError& e) {
                    t.fail("file", fmt::format("this mesh has no inside for CSG: {}", e.what()));
                }
            }
            if (shape_has(kind, SHAPE_ORIENTED) && outward_side(leaf.shape) == 0)
                t.fail("type", fmt::format("this {} is not declared closed: CSG takes a parametric or Bezier surface as a "
                                           "solid only where it encloses one; if it does, say `closed = true` (lancer checks "
                                           "that its patches meet edge to edge)",
                                           type));
            if (const auto* lathe = std::get_if<Lathe>(&leaf.shape); lathe && !lathe->closed)
                t.fail("points", "this lathe's curve is open (it neither ends where it starts nor has both ends on the axis), "
                                 "so it has no inside: CSG combines solids; close the curve");
            const auto* sor = std::get_if<Sor>(&leaf.shape);
            const auto* prism = std::get_if<Prism>(&leaf.shape);
            const bool open = (cone && cone->open) || (sor && sor->open) || (prism && prism->open);
            if (!(shape_has(kind, SHAPE_SOLID) || shape_has(kind, SHAPE_CLOSED) || shape_has(kind, SHAPE_ORIENTED)) || open)
                t.fail(open ? "open" : "type",
                       fmt::format("{}{} has no inside: CSG combines solids (sphere, box, superellipsoid, capped cylinder, cone, sor, prism and lathe, torus, "
                                   "blob, implicit surfaces closed in their box, parametric and Bezier surfaces declared closed, "
                                   "closed meshes, plane as the half-space behind its normal) and CSG objects and groups of them",
                                   open ? "an open " : "a ", type == "spheres" ? "sphere set" : type));
            if (const auto* implicit = std::get_if<ImplicitObject>(&leaf.shape))
                if (auto point = surface::not_proved_positive_on_faces(*implicit->surface))
                    t.fail("type", fmt::format("this {} is not proved closed in its box: CSG takes f < 0 as its inside, "
                                               "and f > 0 could not be proved on the box's faces near ({:.4g}, {:.4g}, {:.4g}) "
                                               "(its coordinates); make the box larger than the solid",
                                               type, point->x, point->y, point->z));
            csg.program.push_back(CSG_LEAF | std::uint32_t(csg.leaves.size()) << 4);
            csg.leaves.push_back(std::move(leaf));
        }
        if (inverse) csg.program.push_back(CSG_NOT);
    }
};

ObjectEntries::ObjectEntries(TableReader& top, const MaterialIndex& named, const MaterialReader& read_inline,
                             std::uint32_t default_material, Scene& scene, TextureLibrary& textures)
    : materials_{named, read_inline, scene},
      reading_(new Reading{materials_, {}, scene, textures, default_material, top.table("declare")}) {}

ObjectEntries::~ObjectEntries() = default;

void ObjectEntries::read(const toml::array& entries, const FileName& file) {
    for_each_table(entries, file, "[[object]]", [&](const toml::table& t, std::size_t) {
        TableReader o(t, file, describe_object("object " + std::to_string(starts_.size()), t));
        reading_->entry(o, reading_->default_material, glm::dmat4(1.0), 0);
        starts_.push_back(reading_->scene.objects.size());
    });
}

void ObjectEntries::reserve(std::size_t entries) {
    reading_->scene.objects.reserve(reading_->scene.objects.size() + entries);
}

}  // namespace lancer
