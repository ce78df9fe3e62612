#pragma once
// A scene of many objects is mostly [[object]] tables. Reading them a batch at a time keeps one
// batch's TOML tree in memory instead of the whole file's: the scanner here finds them, knowing
// just enough TOML (strings, comments, brackets, table headers) to tell a header from text that
// looks like one, and declines wherever splitting the file could read differently from parsing it
// whole (load_scene.cpp then parses it whole).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lancer {

// Whole lines of a scene's text holding `objects` consecutive [[object]] tables and their
// sub-tables ([object.x], [[object.x]]).
struct ObjectBatch {
    std::size_t begin = 0, end = 0;  // byte offsets into the text, each at the start of a line (or its end)
    int first_line = 1;              // the line `begin` starts, 1-based
    std::size_t objects = 0;
};

struct SceneTextParts {
    // The text without the batches' bytes but their line breaks: its lines are the file's.
    std::string head;
    std::vector<ObjectBatch> batches;  // in the file's order
    std::size_t objects = 0;           // in all batches
};

// Splits `text` into its head and batches of at most `per_batch` (> 0) [[object]] tables; nullopt
// where it has none, where it is not valid TOML as far as the scanner sees, or where the root's
// `object` key is defined otherwise than by [[object]] headers (`object = [...]`, `[object]`, a
// quoted "object", an object's sub-table after another table's header).
std::optional<SceneTextParts> split_object_tables(std::string_view text, std::size_t per_batch);

}  // namespace lancer
