// The measurements behind docs/meshes.md ("Mesh files: which reader and why"): one mesh file read
// by lancer's reader, by tinyobjloader or by assimp, best of 3 wall times, and the triangle count.
// Not part of the build (assimp and tinyobjloader are not lancer's dependencies); to rerun it:
//   apt-get install -y libassimp-dev libtinyobjloader-dev
//   g++ -std=c++20 -O2 -Ihost bench/mesh_reader_comparison.cpp -o /tmp/mesh_readers \
//       build/host/liblancer_mesh.a build/host/liblancer_core.a -lassimp -lfmt -lcrypto
//   /usr/bin/time -v /tmp/mesh_readers lancer|tinyobj|assimp FILE     (peak RSS: "Maximum resident set size")
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#define TINYOBJLOADER_IMPLEMENTATION
#define TINYOBJLOADER_USE_DOUBLE
#include <tiny_obj_loader.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/error.hpp"
#include "mesh/mesh_file.hpp"

namespace {

std::size_t read_with(const std::string& reader, const std::string& path) {
    if (reader == "lancer") return lancer::read_mesh_file(path).triangles.size();
    if (reader == "tinyobj") {
        tinyobj::ObjReader r;
        tinyobj::ObjReaderConfig config;
        config.triangulate = true;
        if (!r.ParseFromFile(path, config)) throw std::runtime_error(r.Error());
        if (!r.Warning().empty()) std::fprintf(stderr, "tinyobj warning: %s", r.Warning().c_str());
        std::size_t n = 0;
        for (const auto& s : r.GetShapes()) n += s.mesh.num_face_vertices.size();
        return n;
    }
    Assimp::Importer importer;  // the flags a renderer needs: triangles, shared vertices
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (!scene) throw std::runtime_error(importer.GetErrorString());
    std::size_t n = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) n += scene->mMeshes[i]->mNumFaces;
    return n;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s lancer|tinyobj|assimp FILE\n", argv[0]);
        return 2;
    }
    double best = 1e30;
    std::size_t triangles = 0;
    try {
        for (int run = 0; run < 3; ++run) {
            const auto start = std::chrono::steady_clock::now();
            triangles = read_with(argv[1], argv[2]);
            best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
    } catch (const std::exception& e) {
        std::printf("%s: error: %s\n", argv[1], lancer::format_error(e).c_str());
        return 2;
    }
    std::printf("%s %s: %zu triangles, best of 3: %.1f ms\n", argv[1], argv[2], triangles, best);
}
