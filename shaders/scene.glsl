// Scene buffers and the two queries every ray needs: nearest hit, and "is anything in between".
#ifndef LANCER_SCENE_GLSL
#define LANCER_SCENE_GLSL

layout(std140, set = 0, binding = BINDING_FRAME) uniform FrameBlock { FrameParams frame; };
layout(std430, set = 0, binding = BINDING_PRIMITIVES) readonly buffer PrimitiveBlock { Primitive primitives[]; };
layout(std430, set = 0, binding = BINDING_MATERIALS) readonly buffer MaterialBlock { Material materials[]; };
layout(std430, set = 0, binding = BINDING_LIGHTS) readonly buffer LightBlock { Light lights[]; };

#include "shapes/sphere.glsl"
#include "shapes/plane.glsl"
#include "shapes/rectangle.glsl"
#include "shapes/box.glsl"

bool primitive_intersect(uint index, Ray ray, float t_min, float t_max, out float t_hit) {
    Primitive p = primitives[index];
    switch (p.type) {
        case SHAPE_SPHERE: return sphere_intersect(p, ray, t_min, t_max, t_hit);
        case SHAPE_PLANE: return plane_intersect(p, ray, t_min, t_max, t_hit);
        case SHAPE_RECTANGLE: return rectangle_intersect(p, ray, t_min, t_max, t_hit);
        case SHAPE_BOX: return box_intersect(p, ray, t_min, t_max, t_hit);
    }
    return false;
}

vec3 primitive_normal(uint index, vec3 p) {
    Primitive prim = primitives[index];
    switch (prim.type) {
        case SHAPE_SPHERE: return sphere_normal(prim, p);
        case SHAPE_PLANE: return plane_normal(prim);
        case SHAPE_RECTANGLE: return rectangle_normal(prim);
        case SHAPE_BOX: return box_normal(prim, p);
    }
    return vec3(0.0, 0.0, 1.0);
}

bool closest_hit(Ray ray, float t_min, out Hit hit) {
    hit.t = INFINITY;
    hit.primitive = 0xffffffffu;
    for (uint i = 0u; i < frame.primitive_count; ++i) {
        float t;
        if (primitive_intersect(i, ray, t_min, hit.t, t)) {
            hit.t = t;
            hit.primitive = i;
        }
    }
    if (hit.primitive == 0xffffffffu) return false;
    hit.normal = primitive_normal(hit.primitive, ray.origin + hit.t * ray.dir);
    return true;
}

bool occluded(Ray ray, float t_min, float t_max) {
    for (uint i = 0u; i < frame.primitive_count; ++i) {
        float t;
        if (primitive_intersect(i, ray, t_min, t_max, t)) return true;
    }
    return false;
}

#endif
