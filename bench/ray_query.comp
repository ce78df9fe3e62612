#version 460
// The driver's ray queries doing what `lancer render --samples 1` does for bench/ray_query_*.toml
// (a benchmark, bench/ray_query.sh): one camera ray per pixel through the pixel's centre, its
// closest hit in the driver's acceleration structure, one shadow ray to the one point light
// (first hit ends it), and lancer's shading of a matte material: ambient + diffuse N.L, flat
// triangles, no reflection (shaders/shade.glsl).
#extension GL_EXT_ray_query : require

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform accelerationStructureEXT scene_structure;
// Every mesh's vertices (x, y, z floats) and triangles (three vertex indices), one after another.
layout(std430, binding = 1) readonly buffer Positions { float positions[]; };
layout(std430, binding = 2) readonly buffer Indices { uint indices[]; };
// Per mesh (an instance's custom index): its first index and first vertex in the two above.
layout(std430, binding = 3) readonly buffer MeshStarts { uvec2 mesh_starts[]; };
layout(std430, binding = 4) writeonly buffer Pixels { vec4 pixels[]; };
layout(std140, binding = 5) uniform View {
    vec4 eye;
    vec4 forward;  // unit
    vec4 right;    // unit right * tan(fov / 2) * aspect, as lancer's CameraBasis
    vec4 up;       // unit up * tan(fov / 2)
    vec4 light_position;
    vec4 light_color;
    vec4 ambient;  // the material's ambient * its colour * the scene's ambient light
    vec4 diffuse;  // the material's diffuse * its colour
    vec4 background;
    uvec4 size;    // width, height
} view;

vec3 vertex(uint mesh_first_vertex, uint index) {
    uint v = 3u * (mesh_first_vertex + index);
    return vec3(positions[v], positions[v + 1u], positions[v + 2u]);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (pixel.x >= view.size.x || pixel.y >= view.size.y) return;
    vec2 ndc = vec2(2.0 * (float(pixel.x) + 0.5) / float(view.size.x) - 1.0,
                    1.0 - 2.0 * (float(pixel.y) + 0.5) / float(view.size.y));
    vec3 dir = normalize(view.forward.xyz + ndc.x * view.right.xyz + ndc.y * view.up.xyz);
    vec3 origin = view.eye.xyz;

    rayQueryEXT camera;
    rayQueryInitializeEXT(camera, scene_structure, gl_RayFlagsOpaqueEXT, 0xFFu, origin, 0.0, dir, 1e30);
    while (rayQueryProceedEXT(camera)) {
    }
    vec3 color = view.background.rgb;
    if (rayQueryGetIntersectionTypeEXT(camera, true) == gl_RayQueryCommittedIntersectionTriangleEXT) {
        uvec2 starts = mesh_starts[rayQueryGetIntersectionInstanceCustomIndexEXT(camera, true)];
        uint first = starts.x + 3u * uint(rayQueryGetIntersectionPrimitiveIndexEXT(camera, true));
        vec3 a = vertex(starts.y, indices[first]);
        vec3 b = vertex(starts.y, indices[first + 1u]);
        vec3 c = vertex(starts.y, indices[first + 2u]);
        // A normal goes to the world by the inverse transpose: n * worldToObject.
        mat4x3 to_object = rayQueryGetIntersectionWorldToObjectEXT(camera, true);
        vec3 n = normalize(cross(b - a, c - a) * mat3(to_object));
        if (dot(n, dir) > 0.0) n = -n;  // facing the viewer, as lancer's geometric normal
        vec3 p = origin + rayQueryGetIntersectionTEXT(camera, true) * dir;

        color = view.ambient.rgb;
        vec3 to_light = view.light_position.xyz - p;
        float distance = length(to_light);
        vec3 l = to_light / distance;
        float n_dot_l = dot(n, l);
        if (n_dot_l > 0.0) {  // light behind the surface: no shadow ray, as lancer
            // Off the surface by a little more than float's error at p.
            vec3 start = p + n * (1e-4 * max(1.0, max(abs(p.x), max(abs(p.y), abs(p.z)))));
            rayQueryEXT shadow;
            rayQueryInitializeEXT(shadow, scene_structure, gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT,
                                  0xFFu, start, 0.0, l, distance);
            while (rayQueryProceedEXT(shadow)) {
            }
            if (rayQueryGetIntersectionTypeEXT(shadow, true) == gl_RayQueryCommittedIntersectionNoneEXT)
                color += view.diffuse.rgb * n_dot_l * view.light_color.rgb;
        }
    }
    pixels[pixel.y * view.size.x + pixel.x] = vec4(color, 1.0);
}
