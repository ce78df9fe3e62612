#pragma once
// Typed, located access to one TOML table. Every getter checks the type and that numbers are
// finite, and remembers the key as known; finish() then reports the first unknown key (with a
// "did you mean" suggestion). Errors are SceneErrors at the offending value's line and column.
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <toml++/toml.h>

#include "core/closest_match.hpp"
#include "core/error.hpp"
#include "scene/scene.hpp"

namespace lancer {

class TableReader {
public:
    // `what` names the table in messages, e.g. "[camera]" or "object 'sphere'".
    TableReader(const toml::table& table, FileName file, std::string what);

    bool has(std::string_view key) const;

    double number(std::string_view key, double fallback);
    double required_number(std::string_view key);
    int integer(std::string_view key, int fallback);
    dvec3 vec3(std::string_view key, dvec3 fallback);
    dvec3 required_vec3(std::string_view key);
    std::string string(std::string_view key, std::string fallback);
    std::string required_string(std::string_view key);
    bool boolean(std::string_view key, bool fallback);
    // Sub-tables and arrays are returned as nodes for the caller to read; nullptr when absent.
    const toml::table* table(std::string_view key);
    const toml::array* array(std::string_view key);

    // The raw node of a key of several possible types (nullptr when absent), marked as known.
    const toml::node* node(std::string_view key);

    // Marks a key as known without reading it (for keys consumed elsewhere, such as "type").
    void accept(std::string_view key);
    // Reports the first key that no getter asked for.
    void finish() const;

    SourceLocation location() const;                       // of the table itself
    SourceLocation location(std::string_view key) const;   // of the key's value (or the table)
    [[noreturn]] void fail(std::string_view key, const std::string& message) const;

    const FileName& file() const { return file_; }  // shared by the locations it gives
    const toml::table& table() const { return table_; }
    const std::string& what() const { return what_; }

private:
    const toml::node* get(std::string_view key, bool required);

    const toml::table& table_;
    FileName file_;
    std::string what_;
    // A handful of keys, most shorter than a string's inline buffer: a vector searched in order
    // costs no allocation per key, where a set's nodes cost one each (per object of a million).
    std::vector<std::string> known_;
};

// Value checks shared by the readers; each fails at the key's value with a message naming it.
// Colours are linear RGB; values above 1 are allowed (bright lights), negative ones are not.
dvec3 check_color(TableReader& t, std::string_view key, dvec3 c);
double check_range(TableReader& t, std::string_view key, double v, double lo, double hi);
int check_int_range(TableReader& t, std::string_view key, int v, int lo, int hi);
// The string at `key` (or `fallback`) as the index of one of `names`; anything else is an error
// that lists them, or suggests the nearest: "unknown falloff 'inverse' (did you mean ...?)".
std::size_t one_of(TableReader& t, std::string_view key, std::string_view what, const std::vector<std::string>& names,
                   const std::string& fallback);

SourceLocation location_of(const toml::node& node, const FileName& file);
SourceLocation location_of(const toml::source_region& region, const FileName& file);

// While alive, location_of gives the nodes of `part`'s document, parsed from the lines of a file
// from `first_line` on (a batch of its objects: object_batches.hpp), their place in the file
// (on this thread; other documents' nodes keep theirs).
class FilePartScope {
public:
    FilePartScope(const toml::table& part, int first_line);
    ~FilePartScope();
    FilePartScope(const FilePartScope&) = delete;
    FilePartScope& operator=(const FilePartScope&) = delete;

private:
    const std::string* previous_path_;
    int previous_offset_;
};

// Reads a node as a finite number (integer or float) or a 3-vector of them.
double node_number(const toml::node& node, const std::string& file, const std::string& what);
dvec3 node_vec3(const toml::node& node, const std::string& file, const std::string& what);
// A string without NUL characters (an error at the NUL's position otherwise).
std::string node_string(const toml::node& node, const std::string& file, const std::string& what);

// A list of 2-D points, key = [[a, b], ...] (a sor's, a lathe's, a prism's outline), each with
// where it is: `a` and `b` name the coordinates in messages, `missing` is the message without the key.
struct PointAt {
    glm::dvec2 p;
    SourceLocation at;
};
std::vector<PointAt> read_point_list(TableReader& t, std::string_view key, const char* a, const char* b,
                                     const std::string& missing);

// Calls fn(table, index) for each element of an array of tables ([[light]], [[object]]), and
// fails at an element that is not a table.
template <typename Fn>
void for_each_table(const toml::array& array, const std::string& file, const std::string& what, Fn fn) {
    std::size_t index = 0;
    for (const toml::node& node : array) {
        const toml::table* table = node.as_table();
        if (!table) throw SceneError(location_of(node, file), what + " entries must be tables");
        fn(*table, index++);
    }
}

}  // namespace lancer
