// The scene read in batches of [[object]] tables (scene/object_batches.hpp) against the whole
// document read as one tree: the scanner's split, and the same Scene and errors from both.
#include <filesystem>

#include <gtest/gtest.h>

#include "scene/load_scene.hpp"
#include "scene/object_batches.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// What would differ if a batch read an object otherwise than the whole document does.
void expect_same_scene(const Scene& whole, const Scene& batches, const std::string& what) {
    ASSERT_EQ(whole.objects.size(), batches.objects.size()) << what;
    ASSERT_EQ(whole.materials.size(), batches.materials.size()) << what;
    for (std::size_t i = 0; i < whole.materials.size(); ++i)
        EXPECT_EQ(whole.materials[i].name, batches.materials[i].name) << what << " material " << i;
    EXPECT_EQ(whole.lights.size(), batches.lights.size()) << what;
    EXPECT_EQ(whole.dependencies, batches.dependencies) << what;
    EXPECT_EQ(whole.camera.eye, batches.camera.eye) << what;
    EXPECT_EQ(bool(whole.animation), bool(batches.animation)) << what;
    for (std::size_t i = 0; i < whole.objects.size(); ++i) {
        const Object& a = whole.objects[i];
        const Object& b = batches.objects[i];
        EXPECT_EQ(a.shape.index(), b.shape.index()) << what << " object " << i;
        EXPECT_EQ(a.material, b.material) << what << " object " << i;
        EXPECT_EQ(a.where.file.str(), b.where.file.str()) << what << " object " << i;
        EXPECT_EQ(a.where.line, b.where.line) << what << " object " << i;
        EXPECT_EQ(a.where.column, b.where.column) << what << " object " << i;
        EXPECT_EQ(a.name, b.name) << what << " object " << i;
        EXPECT_EQ(bool(a.placement), bool(b.placement)) << what << " object " << i;
        if (a.placement && b.placement) {
            EXPECT_EQ(a.placement->to_world, b.placement->to_world) << what << " object " << i;
        }
        const auto* sa = std::get_if<Sphere>(&a.shape);
        const auto* sb = std::get_if<Sphere>(&b.shape);
        if (sa && sb) {
            EXPECT_EQ(sa->center, sb->center) << what << " object " << i;
            EXPECT_EQ(sa->radius, sb->radius) << what << " object " << i;
        }
    }
}

// One object a batch: every batch after the first starts lines into the file.
void expect_batches_read_alike(const std::string& text, const std::string& path) {
    const std::optional<SceneTextParts> parts = split_object_tables(text, 1);
    ASSERT_TRUE(parts) << path << ": the scanner declined it";
    const Scene whole = parse_scene(text, path, {}, TomlReading::Whole);
    const Scene batches = parse_scene_batches(text, *parts, path);
    expect_same_scene(whole, batches, path);
}

TEST(TomlBatches, EveryShippedSceneReadsAlikeInBatches) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
        if (entry.path().extension() != ".toml") continue;
        const std::string path = entry.path().string();
        expect_batches_read_alike(test::read_file(path), path);
        ++count;
    }
    EXPECT_GE(count, 10);
}

const char* const kStage = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";

// A sphere's lines: [[object]], type, center, radius.
std::string sphere(int x, const std::string& extra = "") {
    return "[[object]]\ntype = \"sphere\"\n" + extra + "center = [" + std::to_string(x) + ", 0, 0]\nradius = 1\n";
}

TEST(TomlBatches, CrLfLinesReadAlike) {
    const std::string text = std::string(kStage) + sphere(1) + "\n" + sphere(2) + "[material.late]\ncolor = [1, 0, 0]\n" +
                             sphere(3, "material = \"late\" # a comment\n");
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const auto parts = split_object_tables(crlf, 1);
    ASSERT_TRUE(parts);
    ASSERT_EQ(parts->batches.size(), 3u);
    EXPECT_EQ(parts->batches[0].first_line, 4);
    EXPECT_EQ(parts->batches[1].first_line, 9);
    EXPECT_EQ(parts->batches[2].first_line, 15);
    expect_batches_read_alike(crlf, "crlf.toml");
}

TEST(TomlBatches, BatchesHoldTheirObjectsSubTables) {
    const std::string text = std::string(kStage) +   // lines 1-3
                             sphere(0) +                // 4-7
                             "[object.material]\n"      // 8
                             "color = [0, 1, 0]\n"      // 9
                             "[[object.transform]]\n"   // 10
                             "translate = [1, 0, 0]\n" +  // 11
                             sphere(1) +                // 12-15
                             "[[light]]\n"              // 16
                             "position = [0, 5, 0]\n" + // 17
                             sphere(2);                 // 18-21
    const auto parts = split_object_tables(text, 2);
    ASSERT_TRUE(parts);
    ASSERT_EQ(parts->batches.size(), 2u);
    EXPECT_EQ(parts->objects, 3u);
    EXPECT_EQ(parts->batches[0].objects, 2u);
    EXPECT_EQ(text.substr(parts->batches[0].begin, parts->batches[0].end - parts->batches[0].begin),
              text.substr(text.find("[[object]]"), text.find("[[light]]") - text.find("[[object]]")));
    EXPECT_EQ(parts->batches[1].first_line, 18);
    EXPECT_EQ(parts->head, std::string(kStage) + std::string(12, '\n') + "[[light]]\nposition = [0, 5, 0]\n" + std::string(4, '\n'));
    expect_batches_read_alike(text, "sub_tables.toml");
}

TEST(TomlBatches, HeadersInsideStringsArraysAndCommentsAreNotHeaders) {
    const std::string text = std::string(kStage) +
                             "[define]\n"
                             "a = \"\"\"\n[[object]]\ntype = \\\"\"\"\n[[object]]\n\"\"\"\n"
                             "b = '''\n[[object]]\n'''\n"
                             "c = \"\"\"x\"\"\"\"\"\n[[object]]\n"  // a string ending in two quotes, then a real header
                             "type = \"sphere\"\n"
                             "points = [\n[[object]],\n# [[object]]\n]\n"  // an array of arrays, which the object refuses
                             "# [[object]]\n"
                             "[render]\n"
                             "d = ' [[object]] '\n";
    const auto parts = split_object_tables(text, 10);
    ASSERT_TRUE(parts);
    ASSERT_EQ(parts->objects, 1u);
    ASSERT_EQ(parts->batches.size(), 1u);
    EXPECT_EQ(parts->batches[0].first_line, 14);
    EXPECT_EQ(text.substr(parts->batches[0].begin, parts->batches[0].end - parts->batches[0].begin),
              "[[object]]\ntype = \"sphere\"\npoints = [\n[[object]],\n# [[object]]\n]\n# [[object]]\n");
}

TEST(TomlBatches, DeclinesWhereTheRootsObjectIsDefinedOtherwise) {
    const std::string object = "[[object]]\ntype = \"sphere\"\n";
    for (const std::string& text : {
             std::string("object = []\n") + kStage,           // a root key
             std::string("object.type = 1\n") + kStage,       // a dotted root key
             std::string("\"object\" = 1\n") + kStage,        // a quoted root key
             std::string(kStage) + "[object]\ntype = \"box\"\n" + object,
             std::string(kStage) + "[\"object\"]\n" + object,
             std::string(kStage) + object + "[light]\n[object.material]\ncolor = [1, 1, 1]\n",  // after another table
             std::string(kStage) + "[ [object]]\n",
             std::string(kStage) + object + "[[object]] type = 1\n",
             std::string(kStage) + object + "name = \"open\n",  // a string across a line break
             std::string(kStage) + object + "points = [[1, 2]\n",   // an array never closed
             std::string(kStage),                               // no objects at all
         })
        EXPECT_FALSE(split_object_tables(text, 4)) << text;
}

TEST(TomlBatches, ObjectsInLaterBatchesHaveTheirFilesLines) {
    std::string text = std::string(kStage) + "[material.red]\ncolor = [1, 0, 0]\n";
    for (int i = 0; i < 9; ++i) text += sphere(i, "material = \"red\"\n") + "\n";
    const auto parts = split_object_tables(text, 2);
    ASSERT_TRUE(parts);
    ASSERT_EQ(parts->batches.size(), 5u);
    const Scene s = parse_scene_batches(text, *parts, "lines.toml");
    ASSERT_EQ(s.objects.size(), 9u);
    EXPECT_EQ(s.objects[8].where.line, 6 + 8 * 6);
    EXPECT_EQ(s.objects[8].material, 0u);
    EXPECT_EQ(std::get<Sphere>(s.objects[8].shape).center, dvec3(8, 0, 0));
}

// The message of an error where the scene is read whole; "" if it loads.
std::string whole_error(const std::string& text, const std::string& path) {
    try {
        parse_scene(text, path, {}, TomlReading::Whole);
    } catch (const SceneError& e) {
        return format_error(e);
    }
    return "";
}

std::string batches_error(const std::string& text, const std::string& path) {
    try {
        parse_scene(text, path);
    } catch (const SceneError& e) {
        return format_error(e);
    }
    return "";
}

// Twelve spheres of 5 lines from line 4 on, the one at bad_index with `radius_line` for its radius.
std::string many_spheres_with(int bad_index, const std::string& radius_line) {
    std::string text = std::string(kStage);
    for (int i = 0; i < 12; ++i)
        text += "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\n" + (i == bad_index ? radius_line : "radius = 1\n") + "\n";
    return text;
}

TEST(TomlBatches, ErrorsInLateBatchesNameTheWholeParsesPlace) {
    for (const std::string& text : {
             many_spheres_with(10, "radius = -1\n"),                 // the reader's error
             many_spheres_with(11, "radius = \n"),                   // TOML's
             many_spheres_with(9, "radius = 1\nname = \"\"\n"),    // the names' check, after all objects
             many_spheres_with(2, "radius = 1\nname = \"a\"\n") + sphere(0, "name = \"a\"\n"),
             "[render]\nwidth = -5\n" + many_spheres_with(11, "radius = nope\n"),  // TOML's error is reported first
         }) {
        const std::string expected = whole_error(text, "late.toml");
        ASSERT_NE(expected, "") << text;
        EXPECT_EQ(batches_error(text, "late.toml"), expected);
    }
    // Read in batches alone, without the whole parse behind it, the reader's error has its place too.
    const std::string text = many_spheres_with(10, "radius = -1\n");
    const auto parts = split_object_tables(text, 3);
    ASSERT_TRUE(parts);
    try {
        parse_scene_batches(text, *parts, "late.toml");
        FAIL() << "loaded";
    } catch (const SceneError& e) {
        EXPECT_EQ(format_error(e), whole_error(text, "late.toml"));
        EXPECT_EQ(e.where().line, 4 + 10 * 5 + 3);
    }
}

// A file of many batches gives each batch's pages back once read (load_scene): the scene is the
// same, and an error after pages were given back is found again in the file read anew, with the
// whole parse's message and place.
TEST(TomlBatches, AFileReadInBatchesGivesTheSameSceneAndErrorsAfterItsTextIsGivenBack) {
    const int count = 3 * 4096 + 7;  // four batches of load_scene's, each hundreds of KiB
    const auto text_with = [&](int bad, const std::string& radius_line) {
        std::string text = std::string(kStage);
        for (int i = 0; i < count; ++i)
            text += "[[object]]\ntype = \"sphere\"\ncenter = [" + std::to_string(i) + ", 0, 0]\n" +
                    (i == bad ? radius_line : "radius = 0.25\n") + "\n";
        return text;
    };
    const std::string path = test::fresh_dir("batches") + "/many.toml";
    const std::string good = text_with(-1, "");
    test::write_file(path, good);
    expect_same_scene(parse_scene(good, path, {}, TomlReading::Whole), load_scene(path), path);
    for (const auto& [bad, line] : std::vector<std::pair<int, std::string>>{
             {count - 1, "radius = -1\n"},   // the reader's error, in the last batch
             {count - 2, "radius = \n"},     // TOML's
             {5, "radius = -2\n"},           // in the first batch, before anything was given back
         }) {
        const std::string text = text_with(bad, line);
        test::write_file(path, text);
        const std::string expected = whole_error(text, path);
        ASSERT_NE(expected, "") << bad;
        try {
            load_scene(path);
            ADD_FAILURE() << "loaded with an error at object " << bad;
        } catch (const SceneError& e) {
            EXPECT_EQ(format_error(e), expected);
        }
    }
}

}  // namespace
}  // namespace lancer
