// The walk through the tree of a placed set of elements (MeshInfo): a mesh's triangles
// (shapes/mesh.glsl) or a sphere set's spheres (shapes/spheres.glsl), nearest boxes first, in the
// file's coordinates. Twin of host/cpu/shapes/element_walk.hpp (which walks its own tree).

// Whether any hit will do for the ray traced now (scene.glsl's trace_scene sets it for shadow
// rays): a set's walk then stops at the first element it finds, and a Bezier or parametric
// search at its first root. A global, not a parameter of every shape's <name>_intersect, for the
// few families that can use it (CSG, which needs the nearest crossings, calls their searches
// with false).
bool shadow_ray_any_hit = false;

// Element hints: an any-hit walk first tests the element that blocked the last shadow ray to the
// same light (dielectric.glsl's transmittance sets element_hint from what element_blocker said
// then), which saves the walk down the set's tree wherever it still blocks: the samples of a
// pixel and their bounces mostly meet the same triangle. Which element is found first does not
// change whether the light is blocked, so the picture is the same. A sphere set's elements carry
// SPHERE_ELEMENT: the indices of triangles and spheres overlap.
const bool ELEMENT_HINTS = TRACES_MESH || TRACES_SPHERES;
const uint SPHERE_ELEMENT = 0x80000000u;
uint element_hint = NO_PRIMITIVE;
uint element_blocker = NO_PRIMITIVE;  // the element the last any-hit walk found

const int ELEMENT_STACK_SIZE = 64;  // host/accel/bvh.cpp bounds a tree's depth by 60

// The element tests, each in its shape's file: t in (t_min, t_max), or -1. A triangle's takes the
// ray sheared along +z (its axes k, its factors s: shapes/mesh.glsl's ShearedRay).
void shear_axes(vec3 d, out ivec3 k, out vec3 s);
float mesh_element_hit(uint triangle, vec3 origin, ivec3 k, vec3 s, float t_min, float t_max);
float spheres_element_hit(uint sphere, Ray ray, float t_min, float t_max);

// The nearest element hit in (t_min, best), best lowered to it, or with any_hit the first found;
// NO_PRIMITIVE if none. "While-while" as the scene's walk (scene.glsl): interior nodes in one
// loop until a leaf, the leaf's elements after it, so that lavapipe does not run a masked element
// test at every step (docs/performance.md).
uint element_tree_nearest(MeshInfo info, bool spheres, bool any_hit, Ray ray, float t_min, inout float best) {
    vec3 inv_dir = safe_inverse(ray.dir);
    ivec3 k = ivec3(0);
    vec3 s = vec3(0.0);
    if (!spheres) shear_axes(ray.dir, k, s);
    uint tag = spheres ? SPHERE_ELEMENT : 0u;
    if (ELEMENT_HINTS && any_hit) {
        uint hint = element_hint ^ tag;
        if (hint - info.first_element < info.element_count) {
            float t = spheres ? spheres_element_hit(hint, ray, t_min, best) : mesh_element_hit(hint, ray.origin, k, s, t_min, best);
            if (t >= 0.0) {
                best = t;
                element_blocker = element_hint;
                return hint;
            }
        }
    }
    uint best_element = NO_PRIMITIVE;
    uint stack[ELEMENT_STACK_SIZE];
    float stack_t[ELEMENT_STACK_SIZE];
    int sp = 0;
    uint node = info.first_node;
    if (box_entry(mesh_node_at(node).lo.xyz, mesh_node_at(node).hi.xyz, ray.origin, inv_dir, best) == INFINITY) return NO_PRIMITIVE;
    bool visit = true;  // `node` is next; else the next is popped from the stack
    for (;;) {
        MeshNode n;
        for (;;) {
            if (!visit) {
                // Pop the next subtree that may still hold something nearer than the best hit.
                bool found = false;
                while (sp > 0) {
                    --sp;
                    if (stack_t[sp] <= best) {
                        node = stack[sp];
                        found = true;
                        break;
                    }
                }
                if (!found) return best_element;
            }
            n = mesh_node_at(node);
            if (n.count > 0u) break;
            uint near_child = n.first, far_child = n.first + 1u;
            MeshNode a = mesh_node_at(near_child), b = mesh_node_at(far_child);
            float t_near = box_entry(a.lo.xyz, a.hi.xyz, ray.origin, inv_dir, best);
            float t_far = box_entry(b.lo.xyz, b.hi.xyz, ray.origin, inv_dir, best);
            if (t_far < t_near) {
                uint c = near_child; near_child = far_child; far_child = c;
                float f = t_near; t_near = t_far; t_far = f;
            }
            visit = t_near != INFINITY;
            if (visit) {
                if (t_far != INFINITY && sp < ELEMENT_STACK_SIZE) {
                    stack[sp] = far_child;
                    stack_t[sp] = t_far;
                    ++sp;
                }
                node = near_child;
            }
        }
        for (uint i = n.first; i < n.first + n.count; ++i) {
            float t = spheres ? spheres_element_hit(i, ray, t_min, best) : mesh_element_hit(i, ray.origin, k, s, t_min, best);
            if (t >= 0.0) {
                best = t;
                best_element = i;
                if (any_hit) {
                    element_blocker = i | tag;
                    return i;
                }
            }
        }
        visit = false;
    }
    return best_element;
}

// A shape's <name>_intersect for a placement p of a mesh or sphere set (p.data: its MeshInfo):
// uv.x = which element of its set was hit (a whole number: exact in float below 2^24).
bool element_set_intersect(Primitive p, bool spheres, bool any_hit, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv) {
    MeshInfo info = mesh_at(p.data);
    float best = t_max;
    uint element = element_tree_nearest(info, spheres, any_hit, ray, t_min, best);
    if (element == NO_PRIMITIVE) return false;
    t_hit = best;
    uv = vec2(float(element - info.first_element), 0.0);
    return true;
}

// The material of a hit on p (uv.x: which element of its set): the element's own where the
// placement takes the file's (p.p0.y = 1), else the primitive's.
uint element_hit_material(Primitive p, vec2 uv) {
    return p.p0.y != 0.0 ? mesh_material_at(mesh_at(p.data).first_material + uint(uv.x)) : p.material;
}
