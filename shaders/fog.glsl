// POV-Ray's fog along a segment, exactly: its depth, the density integrated from `from` along
// the unit direction `dir` for `len` (INFINITY: a ray that meets nothing). Twin of
// host/scene/fog.cpp (fog_depth), which has the derivation. Constant fog: the length. Ground fog
// (frame.fog_ground): density 1 at heights Y <= 0, 1 / (1 + Y^2) above.
#ifndef LANCER_FOG_GLSL
#define LANCER_FOG_GLSL

float fog_depth(vec3 from, vec3 dir, float len) {
    vec4 g = frame.fog_ground;
    if (g.xyz == vec3(0.0)) return len;
    float a = dot(from, g.xyz) - g.w;  // Y where the segment starts
    float k = dot(dir, g.xyz);         // dY per unit of length
    if (isinf(len)) {
        if (!(k > 0.0)) return INFINITY;
        return (a > 0.0 ? atan(1.0 / a) : 1.5707963 - a) / k;
    }
    float b = a + k * len;
    if (a <= 0.0 && b <= 0.0) return len;
    if (a > 0.0 && b > 0.0) {
        float c = 1.0 + a * b, x = k * len / c;
        return len * (abs(x) < 1e-4 ? 1.0 - x * x / 3.0 : atan(x) / x) / c;  // atan(x) / x
    }
    float lo = min(a, b), hi = max(a, b);
    return len * (atan(hi) - lo) / (hi - lo);
}

#endif
