// Triangle meshes on the CPU reference: hits and misses of a triangle, watertightness (rays
// through vertices and edges of closed meshes cross them exactly twice), smooth normals, texture
// coordinates, the reader's keys and refusals, and convergence of a tessellated sphere to the
// exact one.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "cpu/shapes/shapes.hpp"
#include "image/diff.hpp"
#include "scene/load_scene.hpp"
#include "support/test_meshes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using glm::dvec3;

Mesh mesh_of(TriangleMesh m, bool smooth = false) {
    Mesh mesh;
    mesh.geometry = std::make_shared<const MeshGeometry>(std::move(m));
    mesh.smooth = smooth;
    return mesh;
}

// A mesh object as the loader places it (always, the identity included).
Object placed(Mesh mesh, const glm::dmat4& to_world = glm::dmat4(1.0)) {
    return Object{std::move(mesh), Placement{to_world, glm::inverse(to_world), true}};
}

TriangleMesh one_triangle() {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    m.triangles = {{0, 1, 2}};
    return m;
}

TEST(Mesh, HitsATriangleWithItsBarycentricWeights) {
    const Mesh mesh = mesh_of(one_triangle());
    auto h = cpu::intersect(mesh, cpu::Ray{{0.5, 0.25, 3.0}, {0, 0, -1}}, 0.0, 100.0);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 3.0);
    EXPECT_DOUBLE_EQ(h->uv.x, 0.25);   // weight of vertex 1 (2, 0, 0)
    EXPECT_DOUBLE_EQ(h->uv.y, 0.125);  // of vertex 2 (0, 2, 0)
    EXPECT_EQ(h->part, 0);
    EXPECT_NEAR(std::abs(h->normal.z), 1.0, 1e-15);
    // From behind, beyond t_max, outside, and edge-on: nothing.
    EXPECT_TRUE(cpu::intersect(mesh, cpu::Ray{{0.5, 0.25, -3.0}, {0, 0, 1}}, 0.0, 100.0));
    EXPECT_FALSE(cpu::intersect(mesh, cpu::Ray{{0.5, 0.25, 3.0}, {0, 0, -1}}, 0.0, 2.9));
    EXPECT_FALSE(cpu::intersect(mesh, cpu::Ray{{1.5, 1.5, 3.0}, {0, 0, -1}}, 0.0, 100.0));
    EXPECT_FALSE(cpu::intersect(mesh, cpu::Ray{{-1.0, 0.5, 0.0}, {1, 0, 0}}, 0.0, 100.0));
}

TEST(Mesh, AHitOnAVertexOrAnEdgeCounts) {
    const Mesh mesh = mesh_of(one_triangle());
    for (dvec3 aim : {dvec3(0, 0, 0), dvec3(2, 0, 0), dvec3(1, 1, 0), dvec3(1, 0, 0), dvec3(0, 1, 0)})
        EXPECT_TRUE(cpu::intersect(mesh, cpu::Ray{aim + dvec3(0.3, -0.2, 2.0), -glm::normalize(dvec3(0.3, -0.2, 2.0))}, 0.0, 100.0))
            << aim.x << " " << aim.y;
}

// Every crossing of the line by the mesh, from t_min on: each hit restarts just past itself.
int crossings(const Object& mesh, const cpu::Ray& ray) {
    int count = 0;
    double t = 0.0;
    while (auto h = cpu::intersect(mesh, ray, t, 1e9)) {
        ++count;
        t = h->t + 1e-9;  // far below the mesh's detail, far above rounding
        if (count > 10) break;
    }
    return count;
}

// Rays through each vertex and each edge's midpoint of a closed convex mesh, from outside toward
// a point inside, cross it exactly twice: a crack would let one through, a double hit count 3.
void expect_watertight(const Object& mesh, const dvec3& inside, std::mt19937& rng) {
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    const TriangleMesh& m = std::get<Mesh>(mesh.shape).geometry->mesh();
    std::vector<dvec3> aims;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            aims.push_back(m.positions[t[k]]);
            aims.push_back(0.5 * (m.positions[t[k]] + m.positions[t[(k + 1) % 3]]));
        }
    int failures = 0;
    for (const dvec3& local : aims) {
        const dvec3 aim = dvec3(mesh.placement->to_world * glm::dvec4(local, 1.0));
        const dvec3 origin = inside + 3.0 * (aim - inside) + dvec3(jitter(rng), jitter(rng), jitter(rng));
        const int n = crossings(mesh, cpu::Ray{origin, glm::normalize(aim - origin)});
        if (n != 2 && ++failures <= 5) ADD_FAILURE() << "a ray through (" << aim.x << ", " << aim.y << ", " << aim.z << ") crosses " << n << " times";
    }
    EXPECT_EQ(failures, 0) << "of " << aims.size() << " rays";
}

TEST(Mesh, ClosedMeshesAreWatertightAtTheirVerticesAndEdges) {
    std::mt19937 rng(7);
    expect_watertight(placed(mesh_of(test::icosphere(3))), dvec3(0.01, 0.02, -0.03), rng);
    expect_watertight(placed(mesh_of(test::uv_sphere(12))), dvec3(0.01, 0.02, -0.03), rng);
    // Placed: traced in the file's coordinates through the map.
    const glm::dmat4 m = glm::translate(glm::dmat4(1.0), dvec3(3, -2, 5)) * glm::rotate(glm::dmat4(1.0), 0.7, dvec3(1, 2, 3)) *
                         glm::scale(glm::dmat4(1.0), dvec3(2.0, 0.5, 1.5));
    expect_watertight(placed(mesh_of(test::icosphere(2)), m), dvec3(3, -2, 5), rng);
}

TEST(Mesh, SmoothShadingInterpolatesTheVertexNormalsInTheWorld) {
    TriangleMesh t = one_triangle();
    t.normals = {{0, 0, 1}, glm::normalize(dvec3(1, 0, 1)), glm::normalize(dvec3(0, 1, 1))};
    const glm::dmat4 m = glm::scale(glm::dmat4(1.0), dvec3(1.0, 1.0, 4.0));  // normals tilt toward the flat axis
    const Mesh mesh = mesh_of(t, true);
    const Placement p = *placed(mesh, m).placement;
    const dvec3 at_vertex1 = cpu::mesh_shading_normal(mesh, p, 0, {1.0, 0.0}, dvec3(0, 0, 1));
    const dvec3 expected = glm::normalize(dvec3(1.0, 0.0, 0.25));  // the inverse transpose's
    EXPECT_NEAR(glm::length(at_vertex1 - expected), 0.0, 1e-12);
    // Faced to the side asked for.
    EXPECT_NEAR(glm::length(cpu::mesh_shading_normal(mesh, p, 0, {1.0, 0.0}, dvec3(0, 0, -1)) + expected), 0.0, 1e-12);
    // The middle: the normalised mean.
    const dvec3 mid = cpu::mesh_shading_normal(mesh, p, 0, {1.0 / 3.0, 1.0 / 3.0}, dvec3(0, 0, 1));
    EXPECT_GT(mid.x, 0.0);
    EXPECT_NEAR(mid.x, mid.y, 1e-12);
}

TEST(Mesh, TextureCoordinatesAreTheFilesOrElseBarycentric) {
    TriangleMesh t = one_triangle();
    EXPECT_EQ(cpu::mesh_texture_uv(mesh_of(t), 0, {0.25, 0.5}), glm::dvec2(0.25, 0.5));
    t.uvs = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}};
    const glm::dvec2 uv = cpu::mesh_texture_uv(mesh_of(t), 0, {0.25, 0.5});
    EXPECT_DOUBLE_EQ(uv.x, 0.75);
    EXPECT_DOUBLE_EQ(uv.y, 0.5);
}

TEST(Mesh, VertexNormalsAreComputedWhereTheFileHasNone) {
    const MeshGeometry g(test::icosphere(2));
    EXPECT_TRUE(g.file_normals());
    TriangleMesh bare = test::icosphere(2);
    bare.normals.clear();
    const MeshGeometry computed(bare);
    EXPECT_FALSE(computed.file_normals());
    ASSERT_EQ(computed.mesh().normals.size(), bare.positions.size());
    // On a sphere, the angle-weighted normal is close to the radial direction.
    for (std::size_t i = 0; i < bare.positions.size(); ++i)
        EXPECT_GT(glm::dot(computed.mesh().normals[i], glm::normalize(bare.positions[i])), 0.99);
}

TEST(Mesh, TheTreeHoldsEveryTriangleOnce) {
    const MeshGeometry g(test::uv_sphere(40));
    const ElementTree& tree = g.tree();
    std::vector<int> seen(g.mesh().triangles.size(), 0);
    for (const auto& node : tree.nodes) {
        if (node.count == 0) continue;
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            ++seen[tree.order[i]];
            for (std::uint32_t v : g.mesh().triangles[tree.order[i]])
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(g.mesh().positions[v][a], node.lo[a]);
                    EXPECT_LE(g.mesh().positions[v][a], node.hi[a]);
                }
        }
    }
    for (int n : seen) EXPECT_EQ(n, 1);
}

// A mesh file beside a scene, and the scene's text.
struct MeshScene {
    std::string dir;
    Scene load(const std::string& objects) const {
        const std::string text = "[camera]\neye = [0, 0, 5]\nlook_at = [0, 0, 0]\n[[light]]\nposition = [2, 3, 4]\n" + objects;
        return parse_scene(text, dir + "/scene.toml");
    }
};

MeshScene with_obj(const std::string& obj) {
    MeshScene s{test::fresh_dir("meshes")};
    std::ofstream(s.dir + "/m.obj") << obj;
    return s;
}

const char* const kQuadObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

TEST(Mesh, TheReaderPlacesTheFileAndSharesItBetweenPlacements) {
    const MeshScene s = with_obj(kQuadObj);
    const Scene scene = s.load(
        "[[object]]\ntype = \"mesh\"\nfile = \"m.obj\"\ntransform = { scale = 2, translate = [1, 0, 0] }\n"
        "[[object]]\ntype = \"mesh\"\nfile = \"m.obj\"\nsmooth = true\n");
    ASSERT_EQ(scene.objects.size(), 2u);
    const auto& a = std::get<Mesh>(scene.objects[0].shape);
    const auto& b = std::get<Mesh>(scene.objects[1].shape);
    ASSERT_TRUE(scene.objects[0].placement && scene.objects[1].placement);  // always placed
    EXPECT_TRUE(scene.objects[1].placement->shape_in_object_space);
    EXPECT_EQ(a.geometry, b.geometry);  // read once
    EXPECT_NE(std::find(scene.dependencies.begin(), scene.dependencies.end(), s.dir + "/m.obj"), scene.dependencies.end());
    EXPECT_EQ(a.geometry->mesh().triangles.size(), 2u);  // the quad, fanned
    EXPECT_FALSE(a.smooth);  // the file has no normals
    EXPECT_TRUE(b.smooth);
    auto h = cpu::intersect(scene.objects[0], cpu::Ray{{2.5, 1.5, 3.0}, {0, 0, -1}}, 0.0, 100.0);  // (0.75, 0.75) of the quad, placed
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 3.0);
    EXPECT_FALSE(cpu::intersect(scene.objects[0], cpu::Ray{{0.5, 0.5, 3.0}, {0, 0, -1}}, 0.0, 100.0));
}

// An OBJ's MTL materials dress the mesh where the scene gives it none (itself, its group, its
// placement), once per file however often placed; a material of the scene's replaces them all.
TEST(Mesh, TheFilesMaterialsApplyWhereTheSceneGivesNone) {
    MeshScene s = with_obj("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 3 4\n");
    std::ofstream(s.dir + "/m.mtl") << "newmtl red\nKd 0.9 0.1 0.1\nKs 0.5 0.5 0.5\nNs 30\nnewmtl blue\nKd 0.1 0.2 0.9\nd 0.25\n";
    const Scene scene = s.load("[material.green]\ncolor = [0, 1, 0]\n"
                               "[[object]]\ntype = \"mesh\"\nfile = \"m.obj\"\n"
                               "[[object]]\ntype = \"mesh\"\nfile = \"m.obj\"\ntransform = { translate = [2, 0, 0] }\n"
                               "[[object]]\ntype = \"mesh\"\nfile = \"m.obj\"\nmaterial = \"green\"\n");
    const auto& first = std::get<Mesh>(scene.objects[0].shape);
    const auto& second = std::get<Mesh>(scene.objects[1].shape);
    const auto& third = std::get<Mesh>(scene.objects[2].shape);
    ASSERT_EQ(first.part_materials.size(), 2u);
    EXPECT_EQ(second.part_materials, first.part_materials);  // added once
    EXPECT_EQ(scene.materials.size(), 4u);                     // green, default, red, blue
    const Material& red = scene.materials[first.material_of(0, scene.objects[0].material)];
    const Material& blue = scene.materials[first.material_of(1, scene.objects[0].material)];
    EXPECT_EQ(red.color, dvec3(0.9, 0.1, 0.1));
    EXPECT_DOUBLE_EQ(red.specular, 0.5);
    EXPECT_DOUBLE_EQ(red.shininess, 30.0);
    EXPECT_EQ(blue.transmission, dvec3(0.75));
    EXPECT_TRUE(third.part_materials.empty());
    EXPECT_EQ(scene.materials[third.material_of(1, scene.objects[2].material)].name, "green");
    // The MTL file is a dependency as the OBJ is, once: watch reloads it, the render stamp covers it.
    EXPECT_EQ(std::count(scene.dependencies.begin(), scene.dependencies.end(), s.dir + "/m.mtl"), 1);
    EXPECT_EQ(std::count(scene.dependencies.begin(), scene.dependencies.end(), s.dir + "/m.obj"), 1);
}

TEST(Mesh, TheReaderRefusesWhatItCannotUse) {
    const MeshScene s = with_obj(kQuadObj);
    auto refused = [&](const std::string& objects, int line, const std::string& message) {
        try {
            s.load(objects);
            ADD_FAILURE() << "loaded:\n" << objects;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().line, line) << e.what();
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    };
    refused("[[object]]\ntype = \"mesh\"\n", 6, "file");
    refused("[[object]]\ntype = \"mesh\"\nfile = \"missing.obj\"\n", 8, "missing.obj");
    refused("[[object]]\ntype = \"mesh\"\nfile = \"m.obj\"\nsmooth = 3\n", 9, "smooth");
    refused("[[object]]\ntype = \"mesh\"\nfile = \"m.obj\"\ntransform = { translate = [2e12, 0, 0] }\n", 9, "limit");
}

// A latitude-longitude sphere of ever more triangles, smooth, against the exact sphere on the
// reference: the pictures converge (PSNR rises with every refinement, to a close match).
TEST(Mesh, ATessellatedSphereConvergesToTheExactOne) {
    const std::string base = R"toml(
[render]
width = 96
height = 72
samples = 2
[camera]
eye = [0, 0.5, 4]
look_at = [0, 0, 0]
fov = 35
[[light]]
position = [3, 4, 5]
[material.shiny]
color = [0.8, 0.5, 0.3]
specular = 0.6
shininess = 30
[[object]]
type = "sphere"
center = [0, 0, 0]
radius = 1
material = "shiny"
)toml";
    const Scene exact = test::scene_from_text(base);
    const Rgb8Image reference = to_srgb8(test::render_on(test::Backend::Cpu, exact));
    double last = 0.0;
    for (int rings : {4, 8, 16, 32, 64}) {
        Scene tessellated = exact;
        tessellated.objects[0] = placed(mesh_of(test::uv_sphere(rings), true));
        tessellated.objects[0].material = exact.objects[0].material;
        const double psnr = compare_images(reference, to_srgb8(test::render_on(test::Backend::Cpu, tessellated)), 4).psnr_db;
        EXPECT_GT(psnr, last + 1.0) << rings << " rings";
        last = psnr;
    }
    EXPECT_GT(last, 38.0);
}

}  // namespace
}  // namespace lancer
