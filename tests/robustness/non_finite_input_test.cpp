// NaN and infinity are rejected wherever a number can appear, with the location of the number.
//
// Every numeric value of every shipped scene (scenes/, and the animation test scene, whose
// tables cover every [animation] key) is replaced in turn by nan, inf and -inf; loading must
// fail with "file:line:col" pointing at that value. Values are deduplicated by their key path
// (object type included), so each distinct key is tried once, and scenes other helpers add are
// picked up automatically. Expressions and patch files get the same treatment for their numbers.
#include <cstring>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "scene/load_scene.hpp"
#include "surface/patch_file.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

struct NumberSite {
    std::string signature;  // e.g. object(sphere).center[1]
    int line, column;       // 1-based, of the value
};

// Every integer and float in `node`, with its key path; entries of arrays of tables are named by
// their `type` (objects) or not at all, so that the thousand spheres of many.toml are one site.
void collect(const toml::node& node, const std::string& path, std::vector<NumberSite>& out) {
    if (node.is_integer() || node.is_floating_point()) {
        out.push_back({path, static_cast<int>(node.source().begin.line), static_cast<int>(node.source().begin.column)});
    } else if (const toml::table* t = node.as_table()) {
        for (auto&& [key, value] : *t) collect(value, path + "." + std::string(key.str()), out);
    } else if (const toml::array* a = node.as_array()) {
        for (std::size_t i = 0; i < a->size(); ++i) {
            const toml::node& e = *a->get(i);
            std::string element = path;
            if (const toml::table* t = e.as_table()) {
                if (auto type = (*t)["type"].value<std::string>()) element += "(" + *type + ")";
            } else {
                element += "[" + std::to_string(i) + "]";
            }
            collect(e, element, out);
        }
    }
}

// Byte offset of (line, column) in `text`; columns count bytes (the scenes are ASCII).
std::size_t offset_of(const std::string& text, int line, int column) {
    std::size_t at = 0;
    for (int l = 1; l < line; ++l) at = text.find('\n', at) + 1;
    return at + static_cast<std::size_t>(column - 1);
}

std::size_t literal_length(const std::string& text, std::size_t at) {
    std::size_t end = at;
    while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || std::strchr("+-._", text[end]))) ++end;
    return end - at;
}

std::vector<std::string> scenes_with_every_key() {
    std::vector<std::string> paths = test::scene_files();
    paths.push_back(test::source_path("tests/data/anim/small.toml"));
    return paths;
}

TEST(NonFiniteInput, EveryNumericKeyOfEveryShippedSceneRejectsNanAndInfinityAtItsLocation) {
    std::set<std::string> tried;
    for (const std::string& path : scenes_with_every_key()) {
        const std::string text = test::read_file(path);
        std::vector<NumberSite> sites;
        collect(toml::parse(text, path), "", sites);
        for (const NumberSite& site : sites) {
            if (!tried.insert(site.signature).second) continue;
            std::size_t at = offset_of(text, site.line, site.column);
            std::size_t length = literal_length(text, at);
            ASSERT_GT(length, 0u) << path << ":" << site.line << ":" << site.column;
            for (const char* bad : {"nan", "inf", "-inf"}) {
                std::string changed = text;
                changed.replace(at, length, bad);
                SCOPED_TRACE(path + ":" + std::to_string(site.line) + ":" + std::to_string(site.column) + " " +
                             site.signature + " = " + bad);
                try {
                    parse_scene(changed, path);
                    ADD_FAILURE() << "accepted";
                } catch (const SceneError& e) {
                    EXPECT_EQ(e.where().line, site.line) << e.what();
                    EXPECT_EQ(e.where().column, site.column) << e.what();
                }
            }
        }
    }
    // The walk really went through the scene format: render, camera, lights, materials,
    // every object type, transforms, parameters and the animation tables.
    for (const char* key : {".render.width", ".camera.fov", ".light.position[0]", ".material.floor.checker.size",
                            ".object(sphere).radius", ".object(plane).normal[1]", ".object(rectangle).edge_u[2]",
                            ".object(box).max[0]", ".object(bezier).transform.rotate[0]", ".object(parametric).params.R",
                            ".animation.frames", ".animation.camera_orbit.radius", ".animation.light_orbit.turns",
                            ".animation.object.keys.translate[1]", ".animation.light.keys.time"})
        EXPECT_TRUE(tried.count(key)) << key << " was not found in any shipped scene; keys tried: " << tried.size();
}

// Expressions have no NaN literal, but a NaN can be computed: constant parts that are undefined
// everywhere, or that overflow, are rejected at their column.
TEST(NonFiniteInput, ExpressionsThatCanOnlyBeNanOrInfiniteAreRejectedAtTheirColumn) {
    struct Case {
        std::string x;        // the x expression
        std::string culprit;  // where in it the error must point
    };
    for (const Case& c : {Case{"u + 0/0", "/"}, Case{"u*sqrt(-1)", "sqrt"}, Case{"log(0) + v", "log"},
                          Case{"u + 1e308*1e308", "*"}, Case{"exp(1000) * u", "exp"}, Case{"u + 1e999", "1e999"}}) {
        std::string scene = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\ntype = \"parametric\"\n"
                            "x = \"" + c.x + "\"\ny = \"v\"\nz = \"0\"\nu = [0, 1]\nv = [0, 1]\n";
        SCOPED_TRACE(c.x);
        try {
            parse_scene(scene, "expr.toml");
            ADD_FAILURE() << "accepted";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.where().line, 6) << e.what();
            EXPECT_EQ(e.where().column, 6 + static_cast<int>(c.x.find(c.culprit))) << e.what();  // x = "...
        }
    }
}

// Every number of a patch file (the teapot's first patch and its counts) replaced by nan or inf.
TEST(NonFiniteInput, EveryNumberOfAPatchFileRejectsNanAndInfinityAtItsLocation) {
    const std::string text = test::read_file(test::source_path("scenes/teapot.bpt"));
    int checked = 0, records = 0;
    std::size_t line_start = 0;
    for (int line = 1; records < 18 && line_start < text.size(); ++line) {
        std::size_t line_end = std::min(text.find('\n', line_start), text.find('#', line_start));
        std::size_t next_line = text.find('\n', line_start) + 1;
        bool numbers_here = false;
        for (std::size_t at = line_start; at < line_end;) {
            if (std::isspace(static_cast<unsigned char>(text[at]))) {
                ++at;
                continue;
            }
            numbers_here = true;
            std::size_t length = literal_length(text, at);
            int column = static_cast<int>(at - line_start) + 1;
            for (const char* bad : {"nan", "inf", "-inf"}) {
                std::string changed = text;
                changed.replace(at, length, bad);
                SCOPED_TRACE("teapot.bpt:" + std::to_string(line) + ":" + std::to_string(column) + " = " + bad);
                try {
                    surface::parse_patch_text(changed, "teapot.bpt");
                    ADD_FAILURE() << "accepted";
                } catch (const SceneError& e) {
                    EXPECT_EQ(e.where().line, line) << e.what();
                    EXPECT_EQ(e.where().column, column) << e.what();
                }
            }
            ++checked;
            at += length;
        }
        records += numbers_here;
        line_start = next_line;
    }
    EXPECT_GE(checked, 3 + 16 * 3) << "the count, the degrees and 16 control points";
}

}  // namespace
}  // namespace lancer
