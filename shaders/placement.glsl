// Objects placed by a transform (docs/scene-format.md, "Transforms"). With PLACED_OBJECTS every
// object has a frame (ObjectFrame): the map from the GPU's coordinates to the object's own,
// where its checker and patterns are evaluated, so that they move with it. A shape the host
// could not transform exactly (an ellipsoid, a turned box: OBJECT_SPACE_SHAPES) keeps its own
// coordinates, and rays are carried into them: an affine map keeps t, but the shapes take unit
// directions, so t is measured there in units k times the world's. Twin of
// host/cpu/shapes/placed.cpp and host/cpu/appearance.cpp.
#ifndef LANCER_PLACEMENT_GLSL
#define LANCER_PLACEMENT_GLSL

vec3 object_vector(ObjectFrame f, vec3 d) { return vec3(dot(f.row0.xyz, d), dot(f.row1.xyz, d), dot(f.row2.xyz, d)); }
vec3 object_point(ObjectFrame f, vec3 p) { return object_vector(f, p) + vec3(f.row0.w, f.row1.w, f.row2.w); }

// A gradient (a normal) of the object's coordinates in the GPU's, and back; not normalised.
vec3 world_gradient(ObjectFrame f, vec3 g) { return g.x * f.row0.xyz + g.y * f.row1.xyz + g.z * f.row2.xyz; }
vec3 object_gradient(ObjectFrame f, vec3 g) { return g.x * f.world0.xyz + g.y * f.world1.xyz + g.z * f.world2.xyz; }

vec3 unit_vector(vec3 v) {
    float s = unit_scale(max_abs(v));
    return v * s / length(v * s);
}

// The ray in the frame's object coordinates, with a unit direction; k: object units per world unit along it.
Ray object_ray(ObjectFrame f, Ray ray, out float k) {
    vec3 d = object_vector(f, ray.dir);
    float s = unit_scale(max_abs(d));
    k = length(d * s) / s;
    return Ray(object_point(f, ray.origin), d / k);
}

// The ray in which primitive p's shape is tested (the world's, or its object's), and k.
Ray primitive_ray(Primitive p, Ray ray, out float k) {
    k = 1.0;
    if (!OBJECT_SPACE_SHAPES) return ray;
    ObjectFrame f = object_frame_at(p.object);
    return f.in_object_space != 0u ? object_ray(f, ray, k) : ray;
}

// How far frame f's map of p can stray by rounding: a few roundings of its terms' sizes.
float object_point_rounding(ObjectFrame f, vec3 p) {
    vec3 a = abs(p);
    float terms = max(dot(abs(f.row0.xyz), a) + abs(f.row0.w), max(dot(abs(f.row1.xyz), a) + abs(f.row1.w), dot(abs(f.row2.xyz), a) + abs(f.row2.w)));
    return rounding_bound(8.0, terms);
}

#endif
