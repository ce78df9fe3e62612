#include "mesh/mtl_reader.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "mesh/mesh_assembly.hpp"
#include "mesh/text_lines.hpp"

namespace lancer::mesh {
namespace {

double checked(const TextLines& lines, const LineToken& t, const std::string& what, double lo, double hi) {
    const double x = lines.number(t, what);
    if (auto problem = coordinate_problem(x)) lines.fail(t, fmt::format("the {} {}", what, *problem));
    if (x < lo || x > hi) lines.fail(t, fmt::format("the {} must be between {:g} and {:g}, not {}", what, lo, hi, excerpt(t.text)));
    return x;
}

glm::dvec3 color(const TextLines& lines, const std::string& what) {
    const auto& tok = lines.tokens();
    if (tok.size() >= 2 && (tok[1].text == "spectral" || tok[1].text == "xyz"))
        lines.fail(tok[1], fmt::format("{} {} is not supported: give r g b", what, tok[1].text));
    if (tok.size() != 2 && tok.size() != 4) lines.fail_after_last(fmt::format("{} needs r g b (or one grey value)", what));
    glm::dvec3 c;
    for (int i = 0; i < 3; ++i) c[i] = checked(lines, tok[tok.size() == 2 ? 1 : 1 + i], what + " component", 0.0, 1e6);
    return c;
}

double single(const TextLines& lines, const std::string& what, double lo, double hi) {
    const auto& tok = lines.tokens();
    if (tok.size() != 2) lines.fail_after_last(fmt::format("{} needs exactly one number", tok[0].text));
    return checked(lines, tok[1], what, lo, hi);
}

}  // namespace

std::string resolve_against(const std::string& folder, const std::string& name) {
    const std::filesystem::path p(name);
    if (p.is_absolute() || folder.empty()) return name;
    return (std::filesystem::path(folder) / p).string();
}

void read_mtl(std::string_view text, const std::string& mtl_path, const FileExists& texture_exists,
              std::vector<MeshMaterial>& materials) {
    TextLines lines(text, mtl_path);
    const std::string folder = std::filesystem::path(mtl_path).parent_path().string();
    MeshMaterial* current = nullptr;
    while (lines.next()) {
        const auto& tok = lines.tokens();
        const std::string_view key = tok[0].text;
        if (key == "newmtl") {
            if (tok.size() < 2) lines.fail_after_last("newmtl needs a material name");
            const std::string name(lines.rest_from(1));
            if (std::any_of(materials.begin(), materials.end(), [&](const MeshMaterial& m) { return m.name == name; }))
                lines.fail(tok[1], fmt::format("material {} is defined twice", excerpt(name)));
            current = &materials.emplace_back();
            current->name = name;
            continue;
        }
        const bool used = key == "Kd" || key == "Ks" || key == "Ns" || key == "d" || key == "Tr" || key == "map_Kd";
        if (!used) continue;
        if (!current) lines.fail(tok[0], fmt::format("{} before the first newmtl: it belongs to no material", key));
        if (key == "Kd") {
            current->diffuse = color(lines, "Kd");
        } else if (key == "Ks") {
            current->specular = color(lines, "Ks");
        } else if (key == "Ns") {
            current->shininess = single(lines, "Ns (shininess)", 0.0, 1e6);
        } else if (key == "d") {
            current->opacity = single(lines, "d (opacity)", 0.0, 1.0);
        } else if (key == "Tr") {
            current->opacity = 1.0 - single(lines, "Tr (transparency)", 0.0, 1.0);
        } else {  // map_Kd
            if (tok.size() < 2) lines.fail_after_last("map_Kd needs a texture file name");
            if (tok[1].text.starts_with("-"))
                lines.fail(tok[1], fmt::format("map_Kd options ({}) are not supported: give only the file name", excerpt(tok[1].text)));
            const std::string name(lines.rest_from(1));
            const std::string path = resolve_against(folder, name);
            if (!texture_exists(path))
                lines.fail(tok[1], fmt::format("the texture {} ({}) does not exist", excerpt(name), path));
            current->diffuse_map = path;
        }
    }
}

}  // namespace lancer::mesh
