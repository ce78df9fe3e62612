// Reading mesh files (host/mesh): OBJ with MTL, PLY in its three formats, and every refusal with
// the exact place it names (file:line:column for text, "byte N" for binary PLY).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>

#include "core/error.hpp"
#include "mesh/mesh_file.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/ply_reader.hpp"
#include "support/test_support.hpp"

namespace lancer::mesh {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// MTL files and textures held in memory, as if on disk.
struct FakeFiles {
    std::map<std::string, std::string> mtl;
    std::vector<std::string> textures;
    ObjCompanions companions(const std::string& folder = "") const {
        ObjCompanions c;
        c.folder = folder;
        c.read_mtl = [this](const std::string& path) {
            auto it = mtl.find(path);
            if (it == mtl.end()) throw UserError("No such file or directory");
            return it->second;
        };
        c.texture_exists = [this](const std::string& path) {
            return std::find(textures.begin(), textures.end(), path) != textures.end();
        };
        return c;
    }
};

TriangleMesh obj(const std::string& text, const FakeFiles& files = {}) { return read_obj(text, "m.obj", files.companions()); }

// Runs `read`, which must throw a SceneError at exactly file:line:column whose message contains `part`.
void expect_error(const std::function<void()>& read, const std::string& file, int line, int column, const std::string& part) {
    try {
        read();
        ADD_FAILURE() << "no error; expected one containing: " << part;
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().file.str(), file);
        EXPECT_EQ(e.where().line, line) << e.what();
        EXPECT_EQ(e.where().column, column) << e.what();
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << "message: " << e.what() << "\nexpected: " << part;
    }
}

void expect_obj_error(const std::string& text, int line, int column, const std::string& part, const FakeFiles& files = {}) {
    expect_error([&] { obj(text, files); }, "m.obj", line, column, part);
}

const std::string kTriangleVertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

// ---- OBJ ----

TEST(MeshFileObj, QuadsAndPolygonsAreFannedFromTheirFirstCorner) {
    const TriangleMesh m = obj(kTriangleVertices + "v 0.5 2 0\nf 1 2 3 4\nf 1 2 3 5 4\n");
    ASSERT_EQ(m.triangles.size(), 5u);
    EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(m.triangles[4], (Triangle{0, 4, 3}));
    EXPECT_EQ(m.positions.size(), 5u);
    EXPECT_TRUE(m.normals.empty());
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_TRUE(m.triangle_materials.empty());
    EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
}

TEST(MeshFileObj, NegativeIndicesCountBackFromTheLastVertexDefined) {
    const TriangleMesh m = obj("v 9 9 9\n" + kTriangleVertices + "f -4 -3 -2\nv 5 5 5\nf -1 -5 -4\n");
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions[m.triangles[0][0]], glm::dvec3(0, 0, 0));
    EXPECT_EQ(m.positions[m.triangles[0][2]], glm::dvec3(1, 1, 0));
    EXPECT_EQ(m.positions[m.triangles[1][0]], glm::dvec3(5, 5, 5));
    EXPECT_EQ(m.positions[m.triangles[1][1]], glm::dvec3(0, 0, 0));
    EXPECT_EQ(m.positions[m.triangles[1][2]], glm::dvec3(1, 0, 0));
}

TEST(MeshFileObj, EachDistinctCornerBecomesOneVertexWithBitIdenticalPositions) {
    // Corner 2 of both faces names position 3 with different texture coordinates: two vertices.
    const TriangleMesh m = obj("v 0 0 0\nv 1 0 0\nv 0.1 0.7 0.3\nv 0 1 0\n"
                               "vt 0 0\nvt 1 0\nvt 0.5 1\nvt 0.25 0.75\nvn 0 0 2\n"
                               "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/4/1 4/2/1\n");
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions.size(), 5u);
    EXPECT_EQ(m.uvs.size(), 5u);
    ASSERT_EQ(m.normals.size(), 5u);
    EXPECT_EQ(m.triangles[1][0], m.triangles[0][0]);  // the same (v, vt, vn): the same vertex
    const std::uint32_t a = m.triangles[0][2], b = m.triangles[1][1];
    EXPECT_NE(a, b);
    EXPECT_EQ(std::memcmp(&m.positions[a], &m.positions[b], sizeof(glm::dvec3)), 0);
    EXPECT_EQ(m.uvs[a], glm::dvec2(0.5, 1));
    EXPECT_EQ(m.uvs[b], glm::dvec2(0.25, 0.75));
    EXPECT_EQ(m.normals[a], glm::dvec3(0, 0, 1));  // scaled to unit length
}

TEST(MeshFileObj, CornersWithOnlyNormalsUseTheDoubleSlash) {
    const TriangleMesh m = obj(kTriangleVertices + "vn 0 0 1\nf 1//1 2//1 3//1\n");
    EXPECT_EQ(m.normals.size(), 3u);
    EXPECT_TRUE(m.uvs.empty());
}

TEST(MeshFileObj, MaterialsComeFromTheMtlAndMapKdResolvesAgainstTheMtlsFolder) {
    FakeFiles files;
    files.mtl["models/mats/paint.mtl"] = "# paint\nnewmtl red\nKd 0.9 0.1 0.05\nKs 0.5 0.5 0.5\nNs 64\nd 0.75\n"
                                         "illum 2\nmap_Kd tex/red wood.png\n\nnewmtl glass\nKd 0.2\nTr 0.9\n";
    files.textures = {"models/mats/tex/red wood.png"};
    const TriangleMesh m = read_obj("mtllib mats/paint.mtl\n" + kTriangleVertices +
                                        "f 1 2 3\nusemtl glass\nf 1 3 4\nusemtl red\nf 2 3 4\n",
                                    "models/m.obj", files.companions("models"));
    ASSERT_EQ(m.materials.size(), 3u);  // red, glass, and the one for the face before any usemtl
    EXPECT_EQ(m.materials[0].name, "red");
    EXPECT_EQ(m.materials[0].diffuse, glm::dvec3(0.9, 0.1, 0.05));
    EXPECT_EQ(m.materials[0].specular, glm::dvec3(0.5));
    EXPECT_EQ(m.materials[0].shininess, 64.0);
    EXPECT_EQ(m.materials[0].opacity, 0.75);
    EXPECT_EQ(m.materials[0].diffuse_map, "models/mats/tex/red wood.png");
    EXPECT_EQ(m.materials[1].diffuse, glm::dvec3(0.2));
    EXPECT_NEAR(m.materials[1].opacity, 0.1, 1e-15);
    EXPECT_EQ(m.materials[1].diffuse_map, "");
    EXPECT_EQ(m.materials[2].name, "");
    EXPECT_EQ(m.materials[2].diffuse, glm::dvec3(0.8));
    EXPECT_EQ(m.triangle_materials, (std::vector<std::uint32_t>{2, 1, 0}));
}

TEST(MeshFileObj, ZeroAreaTrianglesAreLeftOutAndCounted) {
    const TriangleMesh m = obj(kTriangleVertices + "v 2 0 0\nf 1 2 3\nf 1 1 2\nf 1 2 5\nf 1 2 3 1\n");
    EXPECT_EQ(m.triangles.size(), 2u);  // the quad's second triangle (1 3 1) is the third degenerate one
    EXPECT_EQ(m.skipped_degenerate, 3u);
}

TEST(MeshFileObj, BadIndicesAreErrorsAtTheirCorner) {
    expect_obj_error(kTriangleVertices + "f 1 2 0\n", 5, 7, "vertex index 0 names nothing");
    expect_obj_error(kTriangleVertices + "f 1 2  7\n", 5, 8, "vertex index 7 is out of range: 4 vertices are defined above this line");
    expect_obj_error(kTriangleVertices + "f -1 -2 -5\n", 5, 9, "vertex index -5 is out of range");
    expect_obj_error("f 1 2 3\n" + kTriangleVertices, 1, 3, "0 vertices are defined above");
    expect_obj_error(kTriangleVertices + "vt 0 0\nf 1/1 2/2 3/1\n", 6, 7, "texture coordinate index 2 is out of range: 1 texture coordinate is defined");
    expect_obj_error(kTriangleVertices + "f 1//1 2//1 3//1\n", 5, 3, "normal index 1 is out of range");
    expect_obj_error(kTriangleVertices + "f 1 2 3x\n", 5, 7, "expected a whole number for the vertex index, found '3x'");
    expect_obj_error(kTriangleVertices + "f 1 2 99999999999999999999\n", 5, 7, "out of range");
    expect_obj_error(kTriangleVertices + "f 1 2/ 3\n", 5, 5, "a face corner is v, v/vt, v//vn or v/vt/vn");
    expect_obj_error(kTriangleVertices + "f 1 2\n", 5, 6, "a face needs at least 3 corners, found 2");
}

TEST(MeshFileObj, BadNumbersAreErrorsAtTheNumber) {
    expect_obj_error("v 0 0 0\nv 1 nan 0\n", 2, 5, "the vertex coordinate nan is not a finite number");
    expect_obj_error("v 0 0 0\nv 1 0 -inf\n", 2, 7, "not a finite number");
    expect_obj_error("v 0 0 0\nv 1 0 1e13\n", 2, 7, "outside lancer's range");
    expect_obj_error("v 0 0 0\nv 1 0 1e999\n", 2, 7, "out of range");
    expect_obj_error("v 0 0\n", 1, 1, "a vertex needs x y z");
    expect_obj_error("v 0 zero 0\n", 1, 5, "expected a number for the vertex coordinate, found 'zero'");
    expect_obj_error("vt 0.5 nan\n", 1, 8, "texture coordinate nan is not a finite number");
    expect_obj_error(kTriangleVertices + "vn 0 0 0\n", 5, 4, "the normal has zero length");
}

TEST(MeshFileObj, InconsistentCornersAndUnknownStatementsAreErrors) {
    expect_obj_error(kTriangleVertices + "vt 0 0\nf 1/1 2/1 3/1\nf 1 3 4\n", 7, 3,
                     "this corner has no texture coordinate and no normal, but the first face's corners (line 6) have one");
    expect_obj_error("v 0 0 0\ncurv 0 1 1 2\n", 2, 1, "free-form geometry ('curv') is not supported");
    expect_obj_error("v 0 0 0\nvv 1 2 3\n", 2, 1, "unknown statement 'vv'");
}

TEST(MeshFileObj, MaterialErrorsNameTheFileAndLine) {
    FakeFiles files;
    files.mtl["a.mtl"] = "newmtl wood\nKd 1 0.5 0.25\nmap_Kd wood.png\n";
    expect_error([&] { obj("mtllib a.mtl\n", files); }, "a.mtl", 3, 8, "the texture 'wood.png' (wood.png) does not exist");
    files.textures = {"wood.png"};
    expect_obj_error("mtllib a.mtl missing.mtl\n", 1, 14, "cannot read the MTL file 'missing.mtl' (missing.mtl): No such file or directory", files);
    expect_obj_error("mtllib a.mtl\n" + kTriangleVertices + "usemtl metal\nf 1 2 3\n", 6, 8,
                     "no material 'metal' in the MTL files named above this line", files);
    expect_obj_error(kTriangleVertices + "usemtl wood\n", 5, 8, "(there is no mtllib line before it)");
    files.mtl["b.mtl"] = "newmtl x\nKd 1 nan 0\n";
    expect_error([&] { obj("mtllib b.mtl\n", files); }, "b.mtl", 2, 6, "not a finite number");
    files.mtl["c.mtl"] = "Kd 1 1 1\n";
    expect_error([&] { obj("mtllib c.mtl\n", files); }, "c.mtl", 1, 1, "Kd before the first newmtl");
    files.mtl["d.mtl"] = "newmtl x\nd 1.5\n";
    expect_error([&] { obj("mtllib d.mtl\n", files); }, "d.mtl", 2, 3, "must be between 0 and 1");
    files.mtl["e.mtl"] = "newmtl x\nnewmtl x\n";
    expect_error([&] { obj("mtllib e.mtl\n", files); }, "e.mtl", 2, 8, "material 'x' is defined twice");
}

TEST(MeshFileObj, AMeshWithoutTrianglesIsAnError) {
    expect_obj_error(kTriangleVertices, 0, 0, "the mesh has no triangles (no faces in the file)");
    expect_obj_error(kTriangleVertices + "f 1 1 2\nf 1 2 2\n", 0, 0, "the mesh has no triangles: all 2 of them have zero area");
}

// ---- PLY ----

// A PLY file put together byte by byte: header text, then values in the file's byte order.
class PlyBytes {
public:
    explicit PlyBytes(bool big_endian = false) : big_(big_endian) {}
    PlyBytes& text(const std::string& s) {
        bytes += s;
        return *this;
    }
    template <class T>
    PlyBytes& put(T value) {
        char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        if (big_) std::reverse(b, b + sizeof(T));
        bytes.append(b, sizeof(T));
        return *this;
    }
    std::string bytes;

private:
    bool big_;
};

TriangleMesh ply(const std::string& bytes) { return read_ply(bytes, "m.ply"); }

void expect_ply_error(const std::string& bytes, int line, int column, const std::string& part) {
    expect_error([&] { ply(bytes); }, "m.ply", line, column, part);
}

const std::string kAsciiHeader = "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 4\nproperty float x\n"
                                 "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n";
const std::string kAsciiSquare = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

TEST(MeshFilePly, AsciiWithNormalsTextureCoordinatesAndPropertiesToPassOver) {
    const TriangleMesh m = ply("ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty float y\nproperty short z\n"
                               "property list uchar float weights\nproperty float nx\nproperty float ny\nproperty float nz\n"
                               "property uchar red\nproperty float s\nproperty float t\n"
                               "element material 1\nproperty list int int things\nproperty float shine\n"
                               "element face 1\nproperty uchar flags\nproperty list uchar uint vertex_index\nend_header\n"
                               "0 0 0 2 0.5 0.5 0 0 3 255 0 0\n"
                               "1 0 0 0 0 5 0 7 0.5 0\n"
                               "0 1 -2 1 9 0 3 0 7 0.25 1\n"
                               "3 1 2 3 4.5\n"
                               "5 3 0 1 2\n");
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[2], glm::dvec3(0, 1, -2));
    ASSERT_EQ(m.normals.size(), 3u);
    EXPECT_EQ(m.normals[0], glm::dvec3(0, 0, 1));
    EXPECT_EQ(m.normals[1], glm::dvec3(0, 1, 0));
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_EQ(m.uvs[1], glm::dvec2(0.5, 0));
    EXPECT_EQ(m.uvs[2], glm::dvec2(0.25, 1));
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
}

// The same mesh in both byte orders, with coordinates and indices of several scalar types.
std::string binary_square(bool big_endian) {
    PlyBytes p(big_endian);
    p.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
           " 1.0\nelement vertex 4\nproperty float x\nproperty double y\nproperty int16 z\nproperty uchar u\nproperty float v\n"
           "element face 1\nproperty list ushort uint16 vertex_indices\nend_header\n");
    const float xs[4] = {0, 1.5f, 1.5f, 0};
    const double ys[4] = {0, 0, 1e-3, 1e-3};
    for (int i = 0; i < 4; ++i) p.put(xs[i]).put(ys[i]).put<std::int16_t>(-300).put<std::uint8_t>(i).put(0.5f * i);
    p.put<std::uint16_t>(4).put<std::uint16_t>(0).put<std::uint16_t>(1).put<std::uint16_t>(2).put<std::uint16_t>(3);
    return p.bytes;
}

TEST(MeshFilePly, BinaryInBothByteOrdersGivesTheSameMesh) {
    for (bool big : {false, true}) {
        SCOPED_TRACE(big ? "big endian" : "little endian");
        const TriangleMesh m = ply(binary_square(big));
        ASSERT_EQ(m.positions.size(), 4u);
        EXPECT_EQ(m.positions[2], glm::dvec3(1.5, 1e-3, -300));
        ASSERT_EQ(m.uvs.size(), 4u);
        EXPECT_EQ(m.uvs[3], glm::dvec2(3, 1.5));
        ASSERT_EQ(m.triangles.size(), 2u);
        EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
        EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
    }
}

TEST(MeshFilePly, TriangleStripsRestartAtMinusOneAndTurnEveryOddTriangle) {
    PlyBytes p;
    p.text("ply\nformat binary_little_endian 1.0\nelement vertex 7\nproperty float x\nproperty float y\nproperty float z\n"
           "element tristrips 1\nproperty list int int vertex_indices\nend_header\n");
    const float xy[7][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {5, 0}, {6, 0}, {5, -1}};
    for (const auto& v : xy) p.put(v[0]).put(v[1]).put(0.0f);
    for (int i : {9, 0, 1, 2, 3, -1, 4, 5, 6, 6}) p.put<std::int32_t>(i);
    const TriangleMesh m = ply(p.bytes);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (Triangle{2, 1, 3}));  // odd: turned around
    EXPECT_EQ(m.triangles[2], (Triangle{4, 5, 6}));  // even again after the restart
    EXPECT_EQ(m.skipped_degenerate, 1u);             // (6 5 6): a strip's usual stitch
    // All three face the same way (+z or -z alike): the strip's winding is kept.
    for (const Triangle& t : m.triangles) {
        const glm::dvec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
        EXPECT_LT(((b - a).x * (c - a).y - (b - a).y * (c - a).x), 0.0);
    }
}

TEST(MeshFilePly, AsciiErrorsGiveLineAndColumn) {
    expect_ply_error(kAsciiHeader + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 4\n", 15, 9, "face 0: vertex index 4 is out of range: the file has 4 vertices");
    expect_ply_error(kAsciiHeader + "0 0 0\n1 0 nan\n1 1 0\n0 1 0\n3 0 1 2\n", 12, 5, "vertex 1: z nan is not a finite number");
    expect_ply_error(kAsciiHeader + "0 0 0\n1 -2e12 0\n1 1 0\n0 1 0\n3 0 1 2\n", 12, 3, "outside lancer's range");
    expect_ply_error(kAsciiHeader + "0 0 0\n1 x 0\n1 1 0\n0 1 0\n3 0 1 2\n", 12, 3, "expected a number, found 'x'");
    expect_ply_error(kAsciiHeader + "0 0 0\n1 0 0\n1 1 0\n", 4, 0, "the header declares 4 vertex items of at least 6 bytes each, but only 18");
    expect_ply_error(kAsciiHeader + kAsciiSquare + "3 0 1.5 2\n", 15, 5, "expected a whole number");
    expect_ply_error(kAsciiHeader + kAsciiSquare + "2 0 1\n", 15, 1, "face 0 has 2 corners: a face needs at least 3");
    expect_ply_error(kAsciiHeader + kAsciiSquare + "3 0 1\n", 15, 0, "the file ends early, in face 1 of the 1");
    expect_ply_error(kAsciiHeader + kAsciiSquare + "3 0 1 2\n7\n", 16, 1, "text after the last element");
    expect_ply_error(kAsciiHeader + kAsciiSquare + "3 0 1 1\n", 0, 0, "all 1 of them have zero area");
}

TEST(MeshFilePly, HeaderErrorsGiveTheirLine) {
    expect_ply_error("plx\n", 1, 1, "not a PLY file");
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex 3\n", 0, 0, "no end_header line");
    expect_ply_error("ply\nformat ascii 2.0\nend_header\n", 2, 14, "PLY version '2.0' is not supported");
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", 3, 16, "must be a whole number");
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", 4, 10, "unknown property type 'quad'");
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n", 3, 0,
                     "the vertex element has no scalar property z");
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                     "property float nx\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n", 3, 0,
                     "some of nx ny nz but not all three");
    expect_ply_error("ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nelement vertex 0\n"
                     "property float x\nproperty float y\nproperty float z\nend_header\n", 3, 0,
                     "the face element comes before the vertex element");
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 0\nproperty list uchar float vertex_indices\nend_header\n", 8, 0,
                     "vertex_indices must hold integers, not float");
}

TEST(MeshFilePly, CountsBeyondWhatTheFileHoldsAreRefusedBeforeAnythingIsAllocated) {
    // A 10 KB file that claims a billion faces.
    PlyBytes p;
    p.text("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1000000000\nproperty list uchar int vertex_indices\nend_header\n");
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) p.put(f);
    while (p.bytes.size() < 10000) p.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    expect_ply_error(p.bytes, 7, 0, "the header declares 1000000000 face items of at least 1 bytes each, but only");
    // 2^31 vertices: within the index range, but not in these bytes.
    expect_ply_error("ply\nformat binary_big_endian 1.0\nelement vertex 2147483648\nproperty float x\nproperty float y\n"
                     "property float z\nend_header\n" + std::string(64, '\0'), 3, 0, "declares 2147483648 vertex items of at least 12 bytes");
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex 4294967296\nproperty uchar x\nproperty uchar y\n"
                     "property uchar z\nend_header\n" + std::string(64, '\0'), 3, 0, "4294967296 vertices are more than lancer's limit of 4294967295");
}

TEST(MeshFilePly, BinaryErrorsGiveTheByteOffset) {
    const std::string good = binary_square(false);
    const std::size_t data = good.find("end_header\n") + 11;
    const std::size_t vertex_bytes = 4 + 8 + 2 + 1 + 4;
    // Cut in the middle of the face list: the message names the end of the file.
    expect_ply_error(good.substr(0, good.size() - 3), 0, 0,
                     "byte " + std::to_string(good.size() - 3) + ": the file ends early, in face 1 of the 1");
    std::string bad = good;
    const std::size_t last_index = good.size() - 2;
    bad[last_index] = 9;
    expect_ply_error(bad, 0, 0, "byte " + std::to_string(last_index) + ": face 0: vertex index 9 is out of range");
    bad = good;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&bad[data + vertex_bytes], &nan, 4);
    expect_ply_error(bad, 0, 0, "byte " + std::to_string(data + vertex_bytes) + ": vertex 1: x nan is not a finite number");
    expect_ply_error(good + "xy", 0, 0, "byte " + std::to_string(good.size()) + ": 2 bytes after the last element");
    // A list length no file this size can hold.
    bad = good;
    bad[good.size() - 10] = bad[good.size() - 9] = '\xff';
    expect_ply_error(bad, 0, 0, "byte " + std::to_string(good.size() - 10) + ": a list of 65535 entries, but only 8 bytes are left");
}

// Found by fuzz_ply: an element without properties may declare any count; reading it must not take time.
TEST(MeshFilePly, AnElementWithoutPropertiesTakesNoTimeWhateverItsCount) {
    const TriangleMesh m = ply("ply\nformat ascii 1.0\nelement nothing 18446744073709551615\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                               "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(m.triangles.size(), 1u);
}

TEST(MeshFilePly, ZeroLengthNormalsAreErrors) {
    expect_ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                     "property float nx\nproperty float ny\nproperty float nz\nend_header\n0 0 0 0 0 0\n",
                     11, 11, "vertex 0: the normal has zero length");
}

// ---- files ----

TEST(MeshFileRead, TheExtensionChoosesTheReaderInAnyCase) {
    const std::string dir = test::fresh_dir("mesh-files");
    test::write_file(dir + "/a.OBJ", "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
    test::write_file(dir + "/a.mtl", "newmtl m\nmap_Kd t.png\n");
    test::write_file(dir + "/t.png", "not read, only found");
    const TriangleMesh m = read_mesh_file(dir + "/a.OBJ");
    EXPECT_EQ(m.triangles.size(), 1u);
    ASSERT_EQ(m.materials.size(), 1u);
    EXPECT_EQ(m.materials[0].diffuse_map, dir + "/t.png");
    test::write_file(dir + "/b.Ply", kAsciiHeader + kAsciiSquare + "4 0 1 2 3\n");
    EXPECT_EQ(read_mesh_file(dir + "/b.Ply").triangles.size(), 2u);
    expect_error([&] { read_mesh_file(dir + "/a.stl"); }, dir + "/a.stl", 0, 0,
                 "lancer reads meshes from .obj and .ply files (by the name's extension), not '.stl'");
    expect_error([&] { read_mesh_file(dir + "/missing.ply"); }, dir + "/missing.ply", 0, 0, "No such file or directory");
    test::write_file(dir + "/b.obj", "mtllib gone.mtl\n");
    expect_error([&] { read_mesh_file(dir + "/b.obj"); }, dir + "/b.obj", 1, 8,
                 "cannot read the MTL file 'gone.mtl' (" + dir + "/gone.mtl): No such file or directory");
}

// ---- the real models (../shared/models, see its README) ----

std::string model(const std::string& name) { return std::string(LANCER_SOURCE_DIR) + "/../shared/models/" + name; }

#define SKIP_WITHOUT(path) \
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "the model " << path << " is absent (../shared/models is not checked out)"

TEST(MeshFileModels, StanfordBunny) {
    const std::string path = model("stanford-bunny.obj");
    SKIP_WITHOUT(path);
    const TriangleMesh m = read_mesh_file(path);
    EXPECT_EQ(m.positions.size(), 35947u);
    EXPECT_EQ(m.triangles.size(), 69451u);
    EXPECT_EQ(m.skipped_degenerate, 0u);
    EXPECT_TRUE(m.normals.empty());
}

// Counted independently (a Python script over the file's strips, winding and exact zero-area test included).
TEST(MeshFileModels, IgeaTriangleStrips) {
    const std::string path = model("igea.ply");
    SKIP_WITHOUT(path);
    const TriangleMesh m = read_mesh_file(path);
    EXPECT_EQ(m.positions.size(), 134345u);
    EXPECT_EQ(m.triangles.size(), 268686u);
    EXPECT_EQ(m.skipped_degenerate, 0u);
}

// 2,930 positions and 3,225 texture coordinates in 3,225 distinct (v, vt) corners; 5,856 triangles.
TEST(MeshFileModels, SpotWithTextureCoordinates) {
    const std::string path = model("spot.obj");
    SKIP_WITHOUT(path);
    const TriangleMesh m = read_mesh_file(path);
    EXPECT_EQ(m.positions.size(), 3225u);
    EXPECT_EQ(m.uvs.size(), 3225u);
    EXPECT_TRUE(m.normals.empty());
    EXPECT_EQ(m.triangles.size(), 5856u);
}

}  // namespace
}  // namespace lancer::mesh
