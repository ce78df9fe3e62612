// What a ray that meets nothing sees under [sky] (scene.hpp's Sky; twin of the CPU reference's
// sky_color in host/cpu/tracer.cpp): its pattern's colour at the unit direction, POV-Ray's
// pigment on the sky sphere; or its ramp at the direction's height, wrapped as POV-Ray's
// gradient y.
#ifndef LANCER_SKY_GLSL
#define LANCER_SKY_GLSL

#include "pattern.glsl"

vec3 sky_color(vec3 dir) {
    if (SKY_HAS_PATTERN) {
        PatternInfo pat = pattern_at(frame.sky_pattern);
        return ramp_color(pat, pattern_value(pat, pattern_space(pat, normalize(dir))).w);
    }
    return ramp_over(frame.sky, frame.sky_colors, fract(dir.y));
}

#endif
