// The GGX (Trowbridge-Reitz) microfacet model: the distribution of normals, Smith's
// height-correlated masking-shadowing, sampling of the visible normals (Heitz 2018), and the
// exact Fresnel reflectance of a conductor (complex index of refraction). Twin of
// host/optics/ggx.cpp, written independently in float; docs/scene-format.md ("Microfacet
// materials") states the formulas. Directions are in the surface's local frame (normal +z),
// pointing away from it; alpha = roughness^2.
#ifndef LANCER_MICROFACET_GLSL
#define LANCER_MICROFACET_GLSL

const float MICROFACET_PI = 3.14159265358979;

float ggx_distribution(float cos_m, float alpha) {
    if (cos_m <= 0.0) return 0.0;
    float a2 = alpha * alpha;
    float d = cos_m * cos_m * (a2 - 1.0) + 1.0;
    return a2 / (MICROFACET_PI * d * d);
}

float ggx_lambda(float cos_theta, float alpha) {
    float c2 = max(cos_theta * cos_theta, 1e-12);  // grazing: Lambda grows without bound, G to 0
    float tan2 = max(0.0, 1.0 - c2) / c2;
    return 0.5 * (sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

float smith_g1(float cos_theta, float alpha) { return 1.0 / (1.0 + ggx_lambda(cos_theta, alpha)); }

float smith_g2(float cos_o, float cos_i, float alpha) {
    return 1.0 / (1.0 + ggx_lambda(cos_o, alpha) + ggx_lambda(cos_i, alpha));
}

// A microfacet normal drawn from those wo sees, from u in [0, 1)^2: the view is stretched to a
// unit-roughness hemisphere, a point drawn on the half disc it sees (the far half squeezed by
// its foreshortening), lifted onto the hemisphere and unstretched.
vec3 sample_visible_normal(vec3 wo, float alpha, vec2 u) {
    vec3 v = normalize(vec3(alpha * wo.xy, wo.z));
    float len2 = dot(v.xy, v.xy);
    vec3 t1 = len2 > 0.0 ? vec3(-v.y, v.x, 0.0) * inversesqrt(len2) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(v, t1);
    float r = sqrt(u.x);
    float phi = 2.0 * MICROFACET_PI * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + v.z);
    p2 = mix(sqrt(max(0.0, 1.0 - p1 * p1)), p2, s);
    vec3 n = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
    return normalize(vec3(alpha * n.xy, max(0.0, n.z)));
}

// D G2 / (4 cos_o cos_i): single-scattering reflection with Fresnel 1.
float ggx_reflection(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    vec3 h = normalize(wo + wi);
    return ggx_distribution(h.z, alpha) * smith_g2(wo.z, wi.z, alpha) / (4.0 * wo.z * wi.z);
}

// Complex numbers as vec2 (re, im).
vec2 complex_mul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 complex_div(vec2 a, vec2 b) { return vec2(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / dot(b, b); }
vec2 complex_sqrt(vec2 z) {  // the root with non-negative real part
    float r = length(z);
    float re = sqrt(max(0.0, 0.5 * (r + z.x)));
    float im = sqrt(max(0.0, 0.5 * (r - z.x)));
    return vec2(re, z.y < 0.0 ? -im : im);
}

// Unpolarised reflectance of a conductor of index eta + i k at incidence cos_i.
float conductor_fresnel_channel(float cos_i, float eta, float k) {
    cos_i = clamp(cos_i, 0.0, 1.0);
    vec2 n = vec2(eta, k);
    vec2 cos_t = complex_sqrt(vec2(1.0, 0.0) - complex_div(vec2(1.0 - cos_i * cos_i, 0.0), complex_mul(n, n)));
    vec2 n_cos_i = n * cos_i;
    vec2 n_cos_t = complex_mul(n, cos_t);
    vec2 p_den = n_cos_i + cos_t, s_den = vec2(cos_i, 0.0) + n_cos_t;
    if (dot(p_den, p_den) == 0.0 || dot(s_den, s_den) == 0.0) return 0.0;  // index 1 at grazing: no interface
    vec2 r_p = complex_div(n_cos_i - cos_t, p_den);
    vec2 r_s = complex_div(vec2(cos_i, 0.0) - n_cos_t, s_den);
    return 0.5 * (dot(r_p, r_p) + dot(r_s, r_s));
}

vec3 conductor_fresnel(float cos_i, vec3 eta, vec3 k) {
    return vec3(conductor_fresnel_channel(cos_i, eta.r, k.r), conductor_fresnel_channel(cos_i, eta.g, k.g),
                conductor_fresnel_channel(cos_i, eta.b, k.b));
}

// An orthonormal basis with n as its third axis (Duff et al. 2017): world = to_world * local.
mat3 basis_around(vec3 n) {
    float sign = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (sign + n.z);
    float b = n.x * n.y * a;
    return mat3(vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), vec3(b, sign + n.y * n.y * a, -n.y), n);
}

#endif
