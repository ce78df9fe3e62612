// Phong shading at a hit: ambient + per unshadowed light (diffuse + specular).
// The CPU reference writes the same model in host/cpu/tracer.cpp; docs/scene-format.md
// ("Shading model") states it as a formula.
#ifndef LANCER_SHADE_GLSL
#define LANCER_SHADE_GLSL

vec3 material_pigment(Material m, vec3 p) {
    if (m.pattern == PATTERN_CHECKER) {
        // Solid 3-D checker, first colour where floor(x)+floor(y)+floor(z) is even (as POV-Ray).
        // The 1e-4 bias keeps surfaces lying on integer planes (the floor at y = 0) on one side.
        vec3 cell = floor(p / m.checker_size + 1e-4);
        int parity = int(cell.x + cell.y + cell.z) & 1;
        return parity == 0 ? m.color.rgb : m.color2.rgb;
    }
    return m.color.rgb;
}

// pigment: the surface's colour there (appearance.glsl). n: the geometric normal, facing the
// viewer (which lights are in front, where shadow rays start); shading_n: the normal that lights
// the surface (n, or tilted by a bump). view_dir is the incoming ray direction.
vec3 shade_local(Material m, vec3 pigment, vec3 p, vec3 n, vec3 shading_n, vec3 view_dir, inout float rays) {
    vec3 color = m.phong.x * pigment * frame.ambient.rgb;
    vec3 mirrored = reflect(view_dir, shading_n);
    vec3 origin = p + ray_offset(p) * n;  // shadow rays start here; shading uses p itself
    for (uint i = 0u; i < frame.light_count; ++i) {
        vec3 l = normalize(lights[i].position.xyz - p);
        if (dot(n, l) <= 0.0) continue;  // light behind the surface: no shadow ray needed
        float n_dot_l = max(0.0, dot(shading_n, l));
        rays += 1.0;
        vec3 to_light = lights[i].position.xyz - origin;
        float dist = length(to_light);
        if (occluded(Ray(origin, to_light / dist), 0.0, dist)) continue;
        color += m.phong.y * n_dot_l * pigment * lights[i].color.rgb;
        float r_dot_l = dot(mirrored, l);
        if (r_dot_l > 0.0 && m.phong.z > 0.0) color += m.phong.z * pow(r_dot_l, m.phong.w) * lights[i].color.rgb;
    }
    return color;
}

#endif
