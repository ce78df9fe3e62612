#include "gpu/packing/primitive_packing.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "scene/shape_bounds.hpp"
#include "scene/prism.hpp"
#include "core/finite.hpp"
#include "core/huge_pages.hpp"
#include "gpu/packing/float_bounds.hpp"
#include "accel/bvh.hpp"
#include "surface/parametric_cells.hpp"

namespace lancer::gpu {
namespace {

// The elements' tree, its leaves' ranges from `first_element` (the elements themselves are
// the caller's to store, in bvh.order).
MeshInfo pack_element_tree(PackedScene& out, const Bvh& bvh, uint first_element, uint count) {
    const MeshInfo info{static_cast<uint>(out.mesh_nodes.size()), first_element, count, NO_MAP};
    reserve_huge(out.mesh_nodes, out.mesh_nodes.size() + bvh.nodes.size());
    for (const lancer::BvhNode& n : bvh.nodes) {
        MeshNode g{};
        pack_box(n.box, g.lo, g.hi);
        g.first = n.count > 0 ? info.first_element + n.first : info.first_node + n.first;
        g.count = n.count;
        out.mesh_nodes.push_back(g);
    }
    return info;
}

// The meshes and sphere sets, once the scene's primitives are planned (pack_element_sets).
struct ElementSetPacker {
    PackedScene& out;
    ElementTreeCache* trees = nullptr;

    // A mesh, once: its triangles in the order of its own BVH's leaves (built here, over their
    // float boxes), that tree, and the triangles' materials where a placement takes them (the
    // same for every such placement).
    void place(uint index, const Mesh& m, uint material, bool first) {
        if (first) out.meshes[index] = pack_mesh(*m.geometry, *element_tree(m.geometry, [&] { return mesh_tree(*m.geometry); }));
        pack_element_materials(out.meshes[index], m, out.mesh_order, material);
    }
    // Each element's material, once per mesh or set, where a placement takes the file's (the same
    // for every such placement); `order` maps the packed elements to the file's.
    template <class Set>
    void pack_element_materials(MeshInfo& info, const Set& set, const std::vector<std::uint32_t>& order, uint material) {
        if (set.part_materials.empty() || info.first_material != NO_MAP) return;
        info.first_material = static_cast<uint>(out.mesh_materials.size());
        for (std::uint32_t k = 0; k < info.element_count; ++k)
            out.mesh_materials.push_back(set.material_of(order[info.first_element + k], material));
    }
    // The tree of a set the scene shares (a mesh's geometry, a sphere set's cloud): the cache's,
    // where the renderer keeps one, else built now.
    template <class Set>
    std::shared_ptr<const Bvh> element_tree(const std::shared_ptr<const Set>& set, const std::function<Bvh()>& build) {
        return trees ? trees->tree(set, build) : std::make_shared<const Bvh>(build());
    }
    // Over the triangles' boxes around their float vertices, which the shader tests.
    static Bvh mesh_tree(const MeshGeometry& geometry) {
        const TriangleMesh& mesh = geometry.mesh();
        std::vector<Aabb> boxes;
        reserve_huge(boxes, mesh.triangles.size());
        for (const auto& t : mesh.triangles) {
            Aabb box;
            for (std::uint32_t v : t) box.extend(dvec3(glm::vec3(mesh.positions[v])));
            boxes.push_back(box);
        }
        // Leaves of 4 to 8 triangles: on lavapipe a step through the tree costs more than a few
        // triangle tests more (the bunny 0.94 of its render time, the 10^6-triangle knot 0.82 and
        // 0.83 of its memory; docs/performance.md).
        return build_bvh_from(std::move(boxes), BvhOptions{.max_leaf_size = 8, .min_leaf_size = 4});
    }
    MeshInfo pack_mesh(const MeshGeometry& geometry, const Bvh& bvh) {
        const TriangleMesh& mesh = geometry.mesh();
        const MeshInfo info = pack_element_tree(out, bvh, static_cast<uint>(out.mesh_triangles.size()), static_cast<uint>(mesh.triangles.size()));
        constexpr glm::dvec2 kCorners[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
        reserve_huge(out.mesh_triangles, out.mesh_triangles.size() + mesh.triangles.size());
        reserve_huge(out.mesh_order, out.mesh_order.size() + mesh.triangles.size());
        for (std::uint32_t index : bvh.order) {
            out.mesh_order.push_back(index);
            const auto& t = mesh.triangles[index];
            MeshTriangle tr{};
            vec4* vertices[3] = {&tr.v0, &tr.v1, &tr.v2};
            vec4* normals[3] = {&tr.n0, &tr.n1, &tr.n2};
            for (int k = 0; k < 3; ++k) {
                const glm::dvec2 uv = mesh.uvs.empty() ? kCorners[k] : mesh.uvs[t[k]];
                *vertices[k] = v4(mesh.positions[t[k]], uv.x);
                *normals[k] = v4(mesh.normals[t[k]], uv.y);
            }
            out.mesh_triangles.push_back(tr);
        }
        return info;
    }
    // A sphere set, once: its spheres in its own BVH's leaf order.
    void place(uint index, const SphereSet& s, uint material, bool first) {
        if (first) out.meshes[index] = pack_sphere_set(*s.cloud, *element_tree(s.cloud, [&] { return sphere_set_tree(*s.cloud); }));
        pack_element_materials(out.meshes[index], s, out.set_order, material);
    }
    static Bvh sphere_set_tree(const SphereCloud& cloud) {
        std::vector<Aabb> boxes;
        reserve_huge(boxes, cloud.spheres().size());
        for (std::uint32_t i = 0; i < cloud.spheres().size(); ++i) {
            Aabb& box = boxes.emplace_back();
            cloud.extend(i, box.lo, box.hi);
        }
        // Leaves of up to 4 whatever the SAH says: half the nodes, and faster on lavapipe (a sphere's
        // test costs about a box's; docs/performance.md).
        return build_bvh_from(std::move(boxes), BvhOptions{.max_leaf_size = 4, .min_leaf_size = 4});
    }
    MeshInfo pack_sphere_set(const SphereCloud& cloud, const Bvh& bvh) {
        const auto& spheres = cloud.spheres();
        const MeshInfo info = pack_element_tree(out, bvh, static_cast<uint>(out.set_spheres.size()), static_cast<uint>(spheres.size()));
        reserve_huge(out.set_spheres, out.set_spheres.size() + spheres.size());
        reserve_huge(out.set_order, out.set_order.size() + spheres.size());
        for (std::uint32_t index : bvh.order) {
            out.set_order.push_back(index);
            out.set_spheres.push_back(SetSphere{spheres[index]});
        }
        return info;
    }
};

// Turns each object into primitives (one, or many for patch sets), each with its box if bounded.
struct PrimitivePacker {
    PackedScene& out;
    std::vector<PrimitiveWithBox>& prims;
    uint material = 0;
    uint object = 0;
    const SpherePacking& spheres;
    ElementSets& sets;

    void add(Primitive p, std::optional<Aabb> box) { prims.emplace_back(p, box); }

    void operator()(const Sphere& s) {
        if (!spheres.by_near_points) {
            add({SHAPE_SPHERE, material, 0, object, v4(s.center, s.radius), v4(s.orientation[0]), v4(s.orientation[1])},
                shape_bounds(s));
            return;
        }
        const dvec3 toward = spheres.eye - s.center;
        const dvec3 n = glm::length(toward) > 0.0 ? glm::normalize(toward) : dvec3(0.0, 1.0, 0.0);
        add({SHAPE_SPHERE, material, std::bit_cast<uint>(float(n.z)), object, v4(s.center + s.radius * n, s.radius),
             v4(s.orientation[0], n.x), v4(s.orientation[1], n.y)},
            shape_bounds(s));
    }
    // A plane's point is any point of it: the shader gets the one nearest its origin (the anchor
    // near the camera), so that its error bound, which grows with the point's distance, stays that
    // of the picture's scale; the texture's (u, v) there go with it (p0.w, p1.w).
    void operator()(const Plane& p) {
        const dvec3 foot = p.normal * glm::dot(p.point, p.normal);
        const dvec3 v_axis = glm::cross(p.u_axis, p.normal);
        add({SHAPE_PLANE, material, 0, object, v4(foot, glm::dot(foot - p.point, p.u_axis)),
             v4(p.normal, glm::dot(foot - p.point, v_axis)), v4(p.u_axis)},
            std::nullopt);
    }
    // Likewise a rectangle's corner becomes (about) its point nearest the origin, with that
    // point's (a, b) along the edges (p0.w, p1.w).
    void operator()(const Rectangle& r) {
        const double uu = glm::dot(r.edge_u, r.edge_u), uv = glm::dot(r.edge_u, r.edge_v), vv = glm::dot(r.edge_v, r.edge_v);
        const double det = uu * vv - uv * uv;
        double a = 0.0, b = 0.0;
        if (det > 0.0) {
            const double pu = glm::dot(-r.corner, r.edge_u), pv = glm::dot(-r.corner, r.edge_v);
            a = std::clamp((pu * vv - pv * uv) / det, 0.0, 1.0);
            b = std::clamp((pv * uu - pu * uv) / det, 0.0, 1.0);
        }
        add({SHAPE_RECTANGLE, material, 0, object, v4(r.corner + a * r.edge_u + b * r.edge_v, a), v4(r.edge_u, b),
             v4(r.edge_v)},
            shape_bounds(r));
    }
    // A disc is packed by (about) its point nearest the origin, as the rectangle: the plane's
    // foot of the origin, pulled in to the rim where it lies beyond it; the centre is then that
    // point + alpha u + beta v in the texture's axes (u, v = u x n), so the shader measures the
    // hit's distance from the centre without ever forming the centre's large coordinates.
    // p0 = (point, radius), p1 = (unit normal, hole radius), p2 = (u axis, alpha), data = beta's bits.
    void operator()(const Disc& d) {
        const dvec3 foot = d.normal * glm::dot(d.center, d.normal);  // of the origin, in the plane
        const dvec3 across = foot - d.center;
        const double reach = glm::length(across);
        const dvec3 point = reach > d.radius ? d.center + across * (d.radius / reach) : foot;
        const dvec3 to_center = d.center - point;
        const dvec3 v_axis = glm::cross(d.u_axis, d.normal);
        add({SHAPE_DISC, material, std::bit_cast<uint>(float(glm::dot(to_center, v_axis))), object, v4(point, d.radius),
             v4(d.normal, d.hole_radius), v4(d.u_axis, glm::dot(to_center, d.u_axis))},
            shape_bounds(d));
    }
    // A cone or cylinder is packed by the point of its axis segment nearest the origin, with the
    // ends' positions along the axis from there (z0 <= 0 <= z1), so that its error bound stays at
    // the picture's scale along a long one, as the disc's: p0 = (point, base radius), p1 = (unit
    // axis, z1), p2 = (texture u axis, cap radius), data = -z0's float bits with the lowest bit
    // replaced by the open flag (an ulp of z0 at most: within its rounding).
    void operator()(const Cone& c) {
        const dvec3 along = c.cap - c.base;
        const double h = glm::length(along);
        const dvec3 axis = along / h;
        const double z = std::clamp(glm::dot(-c.base, axis), 0.0, h);  // the point, from the base
        const uint base_z = (std::bit_cast<uint>(float(z)) & ~1u) | (c.open ? 1u : 0u);
        add({SHAPE_CONE, material, base_z, object, v4(c.base + z * axis, c.base_radius), v4(axis, h - z),
             v4(c.u_axis, c.cap_radius)},
            shape_bounds(c));
    }
    // A torus is compact (its box is R + r about the centre), so it is packed by its centre, as
    // a sphere: p0 = (centre, major radius), p1 = (unit axis, minor radius), p2 = (texture u axis, 0).
    // One primitive with the combination's box; its leaves are packed apart (out.csg_leaves),
    // each with its own frame (out.csg_leaf_frames + its number among the scene's leaves).
    void operator()(const Csg& c) {
        CsgNode node{};
        node.first_leaf = static_cast<uint>(out.csg_leaves.size());
        node.leaf_count = static_cast<uint>(c.leaves.size());
        node.first_op = static_cast<uint>(out.csg_ops.size());
        node.op_count = static_cast<uint>(c.program.size());
        out.csg_ops.insert(out.csg_ops.end(), c.program.begin(), c.program.end());
        std::vector<Primitive> pieces;  // of the surfaces of patches, after the node's leaves
        std::vector<std::size_t> first_pieces;
        for (const Object& leaf : c.leaves) {
            std::vector<PrimitiveWithBox> one;
            const bool own_space = leaf.placement && leaf.placement->shape_in_object_space;
            const SpherePacking leaf_spheres{spheres.by_near_points, own_space ? leaf.placement->object_point(spheres.eye) : spheres.eye};
            const uint frame = out.csg_leaf_frames + out.csg_leaves_framed++;
            pack_object(leaf.shape, leaf.material, frame, leaf_spheres, out, one, sets);
            const int outward = outward_side(leaf.shape);
            if (!shape_has(shape_type(leaf.shape), SHAPE_IN_PIECES)) {
                Primitive p = one.at(0).first;
                if (outward != 0) p.p0.z = float(outward);  // a mesh's (its p0.xy are its own flags)
                out.csg_leaves.push_back(p);
                continue;
            }
            // Its pieces in runs of up to 16 neighbours (a tree's leaves), each run after a
            // primitive that holds its box and length, which the walk tests first.
            std::vector<Aabb> boxes;
            for (const auto& [primitive, primitive_box] : one) boxes.push_back(*primitive_box);
            const Bvh runs = build_bvh(boxes, BvhOptions{.max_leaf_size = 16, .min_leaf_size = 16});
            const auto piece = static_cast<uint>(pieces.size());
            for (const lancer::BvhNode& run : runs.nodes) {
                if (!run.leaf()) continue;
                Primitive& head =
                    pieces.emplace_back(Primitive{shape_type(leaf.shape), leaf.material, run.count, frame, {}, {}, {}});
                pack_box(run.box, head.p0, head.p1);
                for (std::uint32_t k = run.first; k < run.first + run.count; ++k) {
                    Primitive primitive = one[runs.order[k]].first;
                    // A Bezier leaf's box too (it uses none of its own): the walk culls by it.
                    pack_box(boxes[runs.order[k]], primitive.p0, primitive.p1);
                    pieces.push_back(primitive);
                }
            }
            Primitive surface{shape_type(leaf.shape), leaf.material, piece, frame, {}, {},
                              vec4(float(pieces.size() - piece), float(outward), 0.0f, 0.0f)};
            pack_box(runs.nodes.at(0).box, surface.p0, surface.p1);
            first_pieces.push_back(out.csg_leaves.size());
            out.csg_leaves.push_back(surface);
        }
        // The surfaces' pieces (data: the first's index among csg_leaves, made absolute with the
        // leaves' own when scene_packing places them).
        const auto first_piece = static_cast<uint>(out.csg_leaves.size());
        for (std::size_t leaf : first_pieces) out.csg_leaves[leaf].data += first_piece;
        out.csg_leaves.insert(out.csg_leaves.end(), pieces.begin(), pieces.end());
        const auto index = static_cast<uint>(out.csg_nodes.size());
        out.csg_nodes.push_back(node);
        add({SHAPE_CSG, material, index, object, v4(c.lo), v4(c.hi), {}}, Aabb{c.lo, c.hi});
    }
    void operator()(const Torus& o) {
        add({SHAPE_TORUS, material, 0, object, v4(o.center, o.major_radius), v4(o.axis, o.minor_radius), v4(o.u_axis)},
            shape_bounds(o));
    }
    // One primitive per placement (in the file's coordinates: its object's frame carries rays
    // there; its box, the world's, comes from the caller), p0.x = 1 where shaded smooth, p0.y = 1
    // where it takes the file's materials. The mesh itself, its tree and its triangles' materials
    // come later, from pack_element_sets.
    void operator()(const Mesh& m) {
        add({SHAPE_MESH, material, element_set(m.geometry.get(), m), object,
             vec4(m.smooth ? 1.0f : 0.0f, m.part_materials.empty() ? 0.0f : 1.0f, 0.0f, 0.0f), {}, {}},
            shape_bounds(m));
    }
    // As a mesh: one primitive per placement, p0.y = 1 where it takes the file's colours.
    void operator()(const SphereSet& s) {
        add({SHAPE_SPHERES, material, element_set(s.cloud.get(), s), object, vec4(0.0f, s.part_materials.empty() ? 0.0f : 1.0f, 0.0f, 0.0f), {}, {}},
            shape_bounds(s));
    }
    // The index in out.meshes of the set that `shared` names, whose MeshInfo pack_element_sets
    // fills; this placement is noted for it where it is the set's first or takes the file's materials.
    template <class Set>
    uint element_set(const void* shared, const Set& set) {
        const auto [found, added] = out.mesh_indices.try_emplace(shared, static_cast<uint>(out.meshes.size()));
        if (added) out.meshes.emplace_back();
        if (added || !set.part_materials.empty()) sets.placements.push_back({found->second, set, material, added});
        return found->second;
    }
    // One primitive, p0.x its threshold, p1 and p2 its box (the texture's (u, v) across it), data
    // its components' tree (a MeshInfo over BLOB_ELEMENTS, in the tree's leaf order).
    void operator()(const Blob& o) {
        std::vector<Aabb> boxes;
        boxes.reserve(o.components.size());
        for (const BlobComponent& k : o.components) boxes.push_back(Aabb{glm::min(k.a, k.b) - k.radius, glm::max(k.a, k.b) + k.radius});
        const Bvh bvh = build_bvh(boxes, BvhOptions{.max_leaf_size = 4, .min_leaf_size = 4});
        const auto index = static_cast<uint>(out.meshes.size());
        out.meshes.push_back(pack_element_tree(out, bvh, static_cast<uint>(out.blob_elements.size()), static_cast<uint>(o.components.size())));
        for (std::uint32_t i : bvh.order) {
            const BlobComponent& k = o.components[i];
            out.blob_elements.push_back(BlobElement{v4(k.a, k.radius), v4(k.b, k.strength)});
        }
        add({SHAPE_BLOB, material, index, object, vec4(float(o.threshold), 0.0f, 0.0f, 0.0f), v4(o.lo), v4(o.hi)}, shape_bounds(o));
    }
    // One primitive, in its own coordinates (always placed): p0 = (bottom, top, largest radius,
    // 1 where open), p1 = (base's r^2, cap's r^2, segment count), data its first segment (SOR_BANDS).
    void operator()(const Sor& o) {
        const auto first = static_cast<uint>(out.sor_bands.size());
        for (const SorSegment& g : o.segments)
            out.sor_bands.push_back(SorBand{vec4(float(g.a), float(g.b), float(g.c), float(g.d)),
                                            vec4(float(g.y0), float(g.y1), float(g.r_max), 0.0f)});
        add({SHAPE_SOR, material, first, object,
             vec4(float(o.segments.front().y0), float(o.segments.back().y1), float(o.r_max), o.open ? 1.0f : 0.0f),
             vec4(float(o.base_r2), float(o.cap_r2), float(o.segments.size()), 0.0f), {}},
            shape_bounds(o));
    }
    // One primitive, in its own coordinates (always placed): p0 = (bottom, top: scene/prism.hpp's
    // prism_walk_heights; its caps, 1 the bottom's + 2 the top's; its size), p1 = the outline's box
    // (x, z low; x, z high), p2.x = 1 for a conic sweep, data its MeshInfo: a tree over
    // the segments' boxes (x and z; y in [-1, 1]: shapes/prism.glsl walks the plane y = 0), the
    // segments (PRISM_CURVES) in leaf order.
    void operator()(const Prism& o) {
        std::vector<Aabb> boxes;
        boxes.reserve(o.segments.size());
        for (const PrismSegment& s : o.segments) {
            Aabb box;
            for (int i = 0; i <= s.degree; ++i) {
                box.extend(dvec3(s.p[i].x, -1.0, s.p[i].y));
                box.extend(dvec3(s.p[i].x, 1.0, s.p[i].y));
            }
            boxes.push_back(box);
        }
        const Bvh bvh = build_bvh(boxes, BvhOptions{.max_leaf_size = 4, .min_leaf_size = 4});
        const auto index = static_cast<uint>(out.meshes.size());
        out.meshes.push_back(pack_element_tree(out, bvh, static_cast<uint>(out.prism_curves.size()), static_cast<uint>(o.segments.size())));
        for (std::uint32_t i : bvh.order) {
            const PrismSegment& s = o.segments[i];
            PrismCurve g{};
            for (int k = 0; k < 4; ++k) {
                const glm::dvec2& c = s.p[std::min(k, s.degree)];
                g.xs[k] = float(c.x);
                g.zs[k] = float(c.y);
            }
            g.info = vec4(float(s.degree), 0.0f, 0.0f, 0.0f);
            out.prism_curves.push_back(g);
        }
        const Aabb box = *shape_bounds(o);
        const float size = float(std::max({glm::length(box.lo), glm::length(box.hi)}));
        double y0, y1;
        bool cap0, cap1;
        prism_walk_heights(o, y0, y1, cap0, cap1);
        add({SHAPE_PRISM, material, index, object, vec4(float(y0), float(y1), float((cap0 ? 1 : 0) + (cap1 ? 2 : 0)), size),
             vec4(float(o.lo.x), float(o.lo.y), float(o.hi.x), float(o.hi.y)), vec4(o.conic ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f)},
            box);
    }
    // One primitive, in its own coordinates (always placed): p0 = (lowest y, highest y, largest
    // radius, degree), p1 = (segment count, 1 where closed), data its first segment (LATHE_BANDS),
    // each segment's r(s) and y(s) as power coefficients about s = 1/2.
    void operator()(const Lathe& o) {
        const auto first = static_cast<uint>(out.lathe_bands.size());
        for (const LatheSegment& g : o.segments) {
            // Bezier (degree n) to power form in h = s - 1/2: the derivatives at s = 1/2 over k!.
            auto about_half = [&](const std::array<double, 4>& b) {
                std::array<double, 4> w = b, c{};
                const int n = o.degree;
                for (int k = 0; k <= n; ++k) {
                    // w holds the k-th forward differences; the k-th derivative at 1/2 is
                    // n!/(n-k)! times the Bezier of degree n - k of them at 1/2.
                    std::array<double, 4> v = w;
                    for (int level = n - k; level > 0; --level)
                        for (int i = 0; i < level; ++i) v[i] = 0.5 * (v[i] + v[i + 1]);
                    double scale = 1.0;  // n!/(n-k)!/k!
                    for (int j = 0; j < k; ++j) scale = scale * double(n - j) / double(j + 1);
                    c[k] = scale * v[0];
                    for (int i = 0; i + k < n; ++i) w[i] = w[i + 1] - w[i];
                }
                return vec4(float(c[0]), float(c[1]), float(c[2]), float(c[3]));
            };
            out.lathe_bands.push_back(LatheBand{about_half(g.r), about_half(g.y),
                                                vec4(float(g.r_max), float(g.y_lo), float(g.y_hi), float(g.side))});
        }
        add({SHAPE_LATHE, material, first, object, vec4(float(o.y_lo), float(o.y_hi), float(o.r_max), float(o.degree)),
             vec4(float(o.segments.size()), o.closed ? 1.0f : 0.0f, 0.0f, 0.0f), {}},
            shape_bounds(o));
    }
    // One primitive, in its own coordinates (always placed): p0 = (p, q, 1 / p, 1 / q), the
    // exponents 2 / e and 2 / n and their inverses.
    void operator()(const Superellipsoid& o) {
        const double p = 2.0 / o.e, q = 2.0 / o.n;
        add({SHAPE_SUPERELLIPSOID, material, 0, object, vec4(float(p), float(q), float(1.0 / p), float(1.0 / q)), {}, {}},
            shape_bounds(o));
    }
    void operator()(const Box& b) { add({SHAPE_BOX, material, 0, object, v4(b.min), v4(b.max), {}}, shape_bounds(b)); }

    // Each cell of the surface's domain is a primitive with the cell's proved box; the surface
    // itself (its affine map; its equations are compiled into the shader) is one SurfaceInfo.
    void operator()(const ParametricObject& p) {
        auto index = static_cast<uint>(out.surfaces.size());
        const glm::dmat4& m = p.surface->to_world;  // column-major: m[column][row]
        SurfaceInfo info{};
        info.row0 = vec4(float(m[0][0]), float(m[1][0]), float(m[2][0]), float(m[3][0]));
        info.row1 = vec4(float(m[0][1]), float(m[1][1]), float(m[2][1]), float(m[3][1]));
        info.row2 = vec4(float(m[0][2]), float(m[1][2]), float(m[2][2]), float(m[3][2]));
        const glm::dmat4 inv = glm::inverse(m);
        info.inverse0 = vec4(float(inv[0][0]), float(inv[1][0]), float(inv[2][0]), float(inv[3][0]));
        info.inverse1 = vec4(float(inv[0][1]), float(inv[1][1]), float(inv[2][1]), float(inv[3][1]));
        info.inverse2 = vec4(float(inv[0][2]), float(inv[1][2]), float(inv[2][2]), float(inv[3][2]));
        info.domain = vec4(float(p.surface->u0), float(p.surface->u1), float(p.surface->v0), float(p.surface->v1));
        out.surfaces.push_back(info);
        for (const auto& cell : *surface::surface_cells(*p.surface)) {
            // Bounds rounded outward to float; an unbounded one becomes float's largest value,
            // which the search treats as no bound (the packed arrays hold only finite floats).
            auto bound = [](double x, bool upper) {
                constexpr double big = std::numeric_limits<float>::max();
                if (std::isnan(x)) return upper ? float(big) : -float(big);
                if (!(x > -big)) return -float(big);
                if (!(x < big)) return float(big);
                float f = float(x);
                if (upper && double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
                if (!upper && double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
                return f;
            };
            auto lower = [&](const surface::IntervalVec3& b, float w) {
                return vec4(bound(b.x.lo, false), bound(b.y.lo, false), bound(b.z.lo, false), w);
            };
            auto upper = [&](const surface::IntervalVec3& b, float w) {
                return vec4(bound(b.x.hi, true), bound(b.y.hi, true), bound(b.z.hi, true), w);
            };
            auto magnitude = [&](const surface::IntervalVec3& b) {
                auto mag = [&](const surface::Interval& i) {
                    const double m = std::max(-i.lo, i.hi);
                    return bound(m >= 0.0 && !i.is_empty() ? m : surface::kInf, true);
                };
                return vec4(mag(b.x), mag(b.y), mag(b.z), 0.0f);
            };
            ParametricCell c{vec4(float(cell.u0), float(cell.u1), float(cell.v0), float(cell.v1)),
                             lower(cell.Su, float(index)), upper(cell.Su, bound(cell.local_float_pad, true)),
                             lower(cell.Sv, 0.0f), upper(cell.Sv, 0.0f), vec4(0.0f),
                             magnitude(cell.second.Suu), magnitude(cell.second.Suv), magnitude(cell.second.Svv)};
            if (all_finite(cell.centre_point) && glm::all(glm::lessThan(glm::abs(cell.centre_point), dvec3(1e30))))
                c.centre = v4(cell.centre_point, 1.0);
            auto cell_index = static_cast<uint>(out.cells.size());
            out.cells.push_back(c);
            Primitive prim{SHAPE_PARAMETRIC, material, cell_index, object, {}, {}, {}};
            pack_box(Aabb{cell.lo, cell.hi}, prim.p0, prim.p1);
            add(prim, Aabb{cell.lo, cell.hi});
        }
    }

    // One primitive with the box in the surface's own coordinates; its ImplicitInfo carries the
    // map from world space into them (f itself is compiled into the shader).
    void operator()(const ImplicitObject& o) {
        const surface::ImplicitSurface& s = *o.surface;
        auto index = static_cast<uint>(out.implicits.size());
        const glm::dmat4& m = s.to_local;  // column-major: m[column][row]
        ImplicitInfo info{};
        info.row0 = vec4(float(m[0][0]), float(m[1][0]), float(m[2][0]), float(m[3][0]));
        info.row1 = vec4(float(m[0][1]), float(m[1][1]), float(m[2][1]), float(m[3][1]));
        info.row2 = vec4(float(m[0][2]), float(m[1][2]), float(m[2][2]), float(m[3][2]));
        info.texture_box = vec4(float(s.box_lo.x), float(s.box_lo.y), float(s.box_hi.x), float(s.box_hi.y));
        out.implicits.push_back(info);
        // Searched only where the surface can be: a box of 10^6 around a unit sphere is beyond
        // what the float search resolves.
        surface::ImplicitSurface searched = s;
        if (s.search_box) {
            searched.box_lo = (*s.search_box)[0];
            searched.box_hi = (*s.search_box)[1];
        }
        Aabb world;
        surface::implicit_world_bounds(searched, world.lo, world.hi);
        add({SHAPE_IMPLICIT, material, index, object, v4(searched.box_lo), v4(searched.box_hi), {}}, world);
    }

    // Each patch becomes 2^n x 2^n leaves (exact sub-patches, de Casteljau in double): smaller
    // boxes cull more rays before Bezier clipping starts, and clipping converges sooner.
    void operator()(const BezierSurface& s) {
        const int n = 1 << s.subdivision;
        for (std::size_t i = 0; i < s.patches.size(); ++i) {
            for (int a = 0; a < n; ++a) {
                for (int b = 0; b < n; ++b) {
                    double u0 = double(a) / n, u1 = double(a + 1) / n, v0 = double(b) / n, v1 = double(b + 1) / n;
                    surface::BezierPatch leaf = surface::sub_patch(s.patches[i], u0, u1, v0, v1);
                    surface::PatchBounds pb = surface::bounds(leaf);
                    dvec3 origin = 0.5 * (pb.min + pb.max);
                    // A rational patch is the same for weights scaled by any positive factor, but
                    // float is not: weights of 1e-50 would all be 0. Scaled (by a power of two,
                    // exactly) so that the largest is in [1, 2): weights whose largest is 1 stay.
                    // Equal weights become 1: a polynomial patch, which the GPU clips without
                    // the homogeneous coordinate (SCENE_HAS_RATIONAL_PATCHES).
                    const auto [lightest, heaviest] = std::minmax_element(leaf.weights.begin(), leaf.weights.end());
                    int exponent = 0;
                    std::frexp(*heaviest, &exponent);
                    PatchLeaf g{};
                    for (int k = 0; k < 16; ++k) {
                        double w = *lightest == *heaviest ? 1.0 : std::ldexp(leaf.weights[k], 1 - exponent);
                        g.points[k] = v4(leaf.points[k] - origin, w);
                    }
                    g.origin = v4(origin, double(i));
                    g.domain = vec4(float(u0), float(u1), float(v0), float(v1));
                    auto index = static_cast<uint>(out.patches.size());
                    out.patches.push_back(g);
                    add({SHAPE_BEZIER, material, index, object, {}, {}, {}}, Aabb{pb.min, pb.max});
                }
            }
        }
    }
};

}  // namespace

SpherePacking sphere_packing(const Scene& scene) {
    // The centre's float rounding against the picture's detail there: a millionth of the eye's
    // distance from the sphere.
    SpherePacking packing{false, scene.camera.eye};
    for (const Object& o : scene.objects) {
        const auto* s = std::get_if<Sphere>(&o.shape);
        if (!s) continue;
        const double rounding = 0x1p-24 * std::max({std::abs(s->center.x), std::abs(s->center.y), std::abs(s->center.z)});
        const double detail = 1e-6 * std::abs(glm::length(scene.camera.eye - s->center) - s->radius);
        packing.by_near_points |= rounding > detail;
    }
    return packing;
}

void pack_object(const Shape& shape, uint material, uint object, const SpherePacking& spheres, PackedScene& out,
                 std::vector<PrimitiveWithBox>& primitives, ElementSets& sets) {
    std::visit(PrimitivePacker{out, primitives, material, object, spheres, sets}, shape);
}

bool packs_alone(const Object& o) {
    if (o.placement) return false;
    return std::visit([](const auto& shape) {
        using S = std::decay_t<decltype(shape)>;
        return std::is_same_v<S, Sphere> || std::is_same_v<S, Plane> || std::is_same_v<S, Rectangle> ||
               std::is_same_v<S, Box> || std::is_same_v<S, Disc> || std::is_same_v<S, Cone> || std::is_same_v<S, Torus>;
    }, o.shape);
}

void pack_element_sets(const ElementSets& sets, PackedScene& out) {
    ElementSetPacker packer{out, sets.trees};
    for (const ElementSets::Placement& p : sets.placements)
        std::visit([&](const auto& set) { packer.place(p.index, set, p.material, p.first); }, p.set);
}

std::uint64_t bezier_leaf_count(const Scene& scene) {
    std::uint64_t leaves = 0;
    for (const Object& o : scene.objects)
        if (const auto* s = std::get_if<BezierSurface>(&o.shape)) leaves += std::uint64_t(s->patches.size()) << (2 * s->subdivision);
    return leaves;
}

}  // namespace lancer::gpu
