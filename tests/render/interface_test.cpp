// Every scene array of the interface (LANCER_SCENE_ARRAYS in shaders/layout.h) makes the round
// trip host -> texel buffer -> the shader's reader: each element is filled with distinct values
// member by member, read on the device through its reader, written back member by member, and
// must come back as it went. A row added to a struct, a reader that skips a texel or a wrong
// texel format fails here. Nothing is listed by hand: the tests come from the tables.
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu/layout.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "support/gpu_kernel.hpp"

namespace lancer::gpu {
namespace {

// Element values: small whole numbers, exact as uint, int and float, each one different.
struct Counter {
    int next = 1;
    int operator()() { return next++; }
};

#define FILL_VEC4(name) e.name = vec4(float(c()), float(c()), float(c()), float(c()));
#define FILL_VEC4S(name, n) \
    for (vec4 & v : e.name) v = vec4(float(c()), float(c()), float(c()), float(c()));
#define FILL_SCALARS(T0, n0, T1, n1, T2, n2, T3, n3) \
    e.n0 = T0(c());                                  \
    e.n1 = T1(c());                                  \
    e.n2 = T2(c());                                  \
    e.n3 = T3(c());
#define ROWS_VEC4(name) rows.push_back(e.name);
#define ROWS_VEC4S(name, n) rows.insert(rows.end(), std::begin(e.name), std::end(e.name));
#define FILL_UVEC4S(name, n) \
    for (uvec4 & v : e.name) v = uvec4(uint(c()), uint(c()), uint(c()), uint(c()));
#define ROWS_UVEC4S(name, n) \
    for (const uvec4& v : e.name) rows.push_back(vec4(v));
#define ROWS_SCALARS(T0, n0, T1, n1, T2, n2, T3, n3) rows.push_back(vec4(float(e.n0), float(e.n1), float(e.n2), float(e.n3)));

// fill(element, counter) and rows_of(element) for every struct of a ROWS array; one vec4 per
// scalar element.
#define DEFINE_FOR_RESOURCE_ROWS(Element)                                           \
    void fill(Element& e, Counter& c) { LANCER_ROWS_##Element(FILL_VEC4, FILL_VEC4S, FILL_SCALARS, FILL_UVEC4S) } \
    std::vector<vec4> rows_of(const Element& e) {                                   \
        std::vector<vec4> rows;                                                     \
        LANCER_ROWS_##Element(ROWS_VEC4, ROWS_VEC4S, ROWS_SCALARS, ROWS_UVEC4S) return rows;      \
    }
#define DEFINE_FOR_RESOURCE_UINT(Element)
#define DEFINE_FOR_RESOURCE_INT(Element)
#define DEFINE_FOR(NAME, slot, kind, Element, member, reader, what) DEFINE_FOR_##kind(Element)
LANCER_SCENE_ARRAYS(DEFINE_FOR)

void fill(uint& e, Counter& c) { e = uint(c()); }
void fill(int& e, Counter& c) { e = -c(); }
std::vector<vec4> rows_of(uint e) { return {vec4(float(e), 0.0f, 0.0f, 0.0f)}; }
std::vector<vec4> rows_of(int e) { return {vec4(float(e), 0.0f, 0.0f, 0.0f)}; }

// The kernel: invocation i reads element i through `reader` and writes it back as vec4 rows.
std::string kernel(uint kind, const std::string& element, const std::string& reader) {
    std::string body;
    if (kind == RESOURCE_ROWS)
        body = fmt::format(
            "    int k = int(i * {0}_ROWS);\n"
            "    {0} r = {1}(i);\n"
            "    LANCER_ROWS_{0}(WRITE_VEC4, WRITE_VEC4S, WRITE_SCALARS, WRITE_UVEC4S)\n",
            element, reader);
    else
        body = fmt::format("    pixels[i] = vec4(float({}(i)), 0.0, 0.0, 0.0);\n", reader);
    return "#version 450\n"
           "#extension GL_GOOGLE_include_directive : require\n"
           "#extension GL_EXT_control_flow_attributes : require\n"
           "#include \"interface.glsl\"\n"
           "layout(local_size_x = 1) in;\n"
           "#define WRITE_VEC4(name) pixels[k++] = r.name;\n"
           "#define WRITE_VEC4S(name, n) for (int j = 0; j < (n); ++j) pixels[k++] = r.name[j];\n"
           "#define WRITE_UVEC4S(name, n) for (int j = 0; j < (n); ++j) pixels[k++] = vec4(r.name[j]);\n"
           "#define WRITE_SCALARS(T0, n0, T1, n1, T2, n2, T3, n3) "
           "pixels[k++] = vec4(float(r.n0), float(r.n1), float(r.n2), float(r.n3));\n"
           "void main() {\n"
           "    uint i = gl_GlobalInvocationID.x;\n" +
           body + "}\n";
}

template <class Element>
void expect_round_trip(std::vector<Element> PackedScene::*array, uint kind, const char* element, const char* reader) {
    constexpr std::uint32_t kElements = 3;
    PackedScene scene;
    Counter counter;
    std::vector<vec4> expected;
    for (std::uint32_t i = 0; i < kElements; ++i) {
        Element e{};
        fill(e, counter);
        (scene.*array).push_back(e);
        for (const vec4& row : rows_of(e)) expected.push_back(row);
    }
    std::vector<vec4> io(expected.size(), vec4(-1.0f));
    std::vector<vec4> got = test::GpuKernel(kernel(kind, element, reader)).run(scene, FrameParams{}, io, kElements);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t k = 0; k < got.size(); ++k)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(got[k][c], expected[k][c]) << element << " row " << k << " component " << c;
}

#define ROUND_TRIP_TEST(NAME, slot, kind, Element, member, reader, what) \
    TEST(Interface, NAME##ReadBackThroughItsReader) { expect_round_trip(&PackedScene::member, kind, #Element, #reader); }
LANCER_SCENE_ARRAYS(ROUND_TRIP_TEST)

}  // namespace
}  // namespace lancer::gpu
