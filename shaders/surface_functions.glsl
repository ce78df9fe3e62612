// The user's expression surfaces, as GLSL. This file on disk is the stub used when a scene has
// none (it is what the embedded SPIR-V is built from); for a scene with parametric or implicit
// surfaces the host generates a replacement (host/gpu/shaders/surface_codegen.cpp) with functions for
// each surface, values and exact derivatives by forward differentiation (and, for implicit
// surfaces, interval enclosures), and compiles the tracer again with it at run time. User text
// never reaches GLSL: the generator prints the parsed expression tree.
#define LANCER_PARAMETRIC_SURFACES 0
#define LANCER_IMPLICIT_SURFACES 0

void surface_eval(uint surface, vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv) {
    P = vec3(0.0);
    Pu = vec3(0.0);
    Pv = vec3(0.0);
}
