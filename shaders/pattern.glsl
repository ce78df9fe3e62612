// Procedural patterns: a scalar function f of the position (noise, turbulence, marble, wood),
// with its gradient, shown through a colour ramp or used as a bump. The rules are in
// docs/scene-format.md ("Patterns"). Twin of host/cpu/pattern.cpp.
#ifndef LANCER_PATTERN_GLSL
#define LANCER_PATTERN_GLSL

#include "noise.glsl"

// f at pattern-space point q, with its gradient there: (gradient, value). Noise is called from
// one place only (code size costs speed on lavapipe, even where it never runs): plain noise is a
// single octave of the sum, turbulence, marble and wood sum omega^i |noise(lambda^i q)|.
vec4 pattern_value(PatternInfo pat, vec3 q) {
    const float TWO_PI = 6.28318530717959;
    bool plain = pat.type == PATTERN_NOISE;
    uint octaves = plain ? 1u : pat.octaves;
    vec4 t = vec4(0.0);
    float amplitude = 1.0, frequency = 1.0;
    for (uint i = 0u; i < octaves; ++i) {
        vec4 n = perlin_noise(frequency * q);
        float sign_n = plain || n.w >= 0.0 ? 1.0 : -1.0;
        t += sign_n * amplitude * vec4(frequency * n.xyz, n.w);
        amplitude *= pat.params.y;
        frequency *= pat.params.z;
    }
    if (plain) return 0.5 * t + vec4(0.0, 0.0, 0.0, 0.5);
    if (pat.type == PATTERN_TURBULENCE) return t;
    float turbulence = pat.params.x;
    if (pat.type == PATTERN_MARBLE) {
        // Bands across x, one period per unit, bent by turbulence.
        float phase = TWO_PI * (q.x + turbulence * t.w);
        vec3 dphase = TWO_PI * (vec3(1.0, 0.0, 0.0) + turbulence * t.xyz);
        return vec4(0.5 * cos(phase) * dphase, 0.5 + 0.5 * sin(phase));
    }
    // Wood: rings around the z axis, one per unit of radius, as a triangle wave.
    float radius = length(q.xy);
    vec3 dradius = radius > 0.0 ? vec3(q.xy / radius, 0.0) : vec3(0.0);
    float r = radius + turbulence * t.w;
    vec3 dr = dradius + turbulence * t.xyz;
    float fraction = fract(r);
    return vec4((fraction < 0.5 ? 2.0 : -2.0) * dr, 1.0 - 2.0 * abs(fraction - 0.5));
}

vec3 pattern_space(PatternInfo pat, vec3 p) {
    return vec3(dot(pat.row0.xyz, p) + pat.row0.w, dot(pat.row1.xyz, p) + pat.row1.w, dot(pat.row2.xyz, p) + pat.row2.w);
}

// The ramp's colour at t: the first colour below the first stop, the last above the last.
// The ramp of `count` stops (rgb, w = the stop) at t (host/cpu/pattern.cpp's ramp_color).
vec3 ramp_over(vec4 colors[PATTERN_MAX_COLORS], uint count, float t) {
    vec3 color = colors[0].rgb;
    for (uint i = 1u; i < count; ++i) {
        vec4 a = colors[i - 1u];
        vec4 b = colors[i];
        if (t >= b.w) {
            color = b.rgb;
        } else {
            if (t > a.w) color = mix(a.rgb, b.rgb, (t - a.w) / (b.w - a.w));
            break;
        }
    }
    return color;
}

vec3 ramp_color(PatternInfo pat, float t) { return ramp_over(pat.colors, pat.color_count, t); }

// The gradient g of a bump's pattern (in pattern space) in its object's coordinates.
vec3 pattern_gradient(PatternInfo pat, vec3 g) { return g.x * pat.row0.xyz + g.y * pat.row1.xyz + g.z * pat.row2.xyz; }

// n (unit, facing the viewer) tilted by the world gradient of a bump's pattern, multiplied by the
// pattern's mean scale (so scaling a bump keeps its depth).
vec3 bumped_normal(PatternInfo pat, vec3 world, vec3 n) {
    return normalize(n - pat.params.w * (world - dot(world, n) * n));
}

#endif
