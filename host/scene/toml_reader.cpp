#include "scene/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "core/magnitude.hpp"
#include "scene/pov_colors.hpp"
#include "scene/pov_ray_words.hpp"
#include "scene/scene_values.hpp"
#include "scene/string_position.hpp"

namespace lancer {

namespace {

// The document of the FilePartScope alive on this thread (its nodes share its source path) and
// the lines before its first.
thread_local const std::string* part_path = nullptr;
thread_local int part_line_offset = 0;

}  // namespace

FilePartScope::FilePartScope(const toml::table& part, int first_line)
    : previous_path_(part_path), previous_offset_(part_line_offset) {
    part_path = part.source().path.get();
    part_line_offset = first_line - 1;
}

FilePartScope::~FilePartScope() {
    part_path = previous_path_;
    part_line_offset = previous_offset_;
}

SourceLocation location_of(const toml::source_region& region, const FileName& file) {
    const int offset = part_path && region.path.get() == part_path ? part_line_offset : 0;
    return {file, static_cast<int>(region.begin.line) + offset, static_cast<int>(region.begin.column)};
}

SourceLocation location_of(const toml::node& node, const FileName& file) {
    return location_of(node.source(), file);
}

namespace {

const char* type_name(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return "an array";
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a number";
        case toml::node_type::boolean: return "a boolean";
        default: return "a date/time";
    }
}

}  // namespace

double node_number(const toml::node& node, const std::string& file, const std::string& what) {
    double value;
    if (auto i = node.as_integer()) {
        value = static_cast<double>(i->get());
    } else if (auto f = node.as_floating_point()) {
        value = f->get();
    } else if (SceneValues* values = current_scene_values(); values && node.is_string()) {
        value = values->evaluate(node, file, what);  // an expression of the scene's named numbers
    } else {
        throw SceneError(location_of(node, file), what + " must be a number or an expression (a string), not " + type_name(node));
    }
    if (!std::isfinite(value)) throw SceneError(location_of(node, file), fmt::format("{} must be finite, not {}", what, value));
    if (std::abs(value) > kMaxMagnitude)
        throw SceneError(location_of(node, file),
                         fmt::format("{} is {:g}, beyond lancer's limit of {:g} for any number", what, value, kMaxMagnitude));
    return value;
}

std::vector<PointAt> read_point_list(TableReader& t, std::string_view key, const char* a, const char* b,
                                     const std::string& missing) {
    const toml::array* list = t.array(key);
    if (!list) t.fail("type", missing);
    std::vector<PointAt> points;
    points.reserve(list->size());
    for (std::size_t i = 0; i < list->size(); ++i) {
        const toml::node& node = *list->get(i);
        const SourceLocation at = location_of(node, t.file());
        const toml::array* pair = node.as_array();
        const std::string what = fmt::format("{} {}[{}]", t.what(), key, i);
        if (!pair || pair->size() != 2) throw SceneError(at, fmt::format("{}: expected [{}, {}]", what, a, b));
        points.push_back({glm::dvec2(node_number(*pair->get(0), t.file(), what + " " + a),
                                     node_number(*pair->get(1), t.file(), what + " " + b)),
                          at});
    }
    return points;
}

dvec3 node_vec3(const toml::node& node, const std::string& file, const std::string& what) {
    if (SceneValues* values = current_scene_values(); values && node.is_string()) {  // a defined vector or a colour's name
        const std::string& name = node.as_string()->get();
        if (auto v = values->vector(name)) return *v;
        std::set<std::string, std::less<>> names;
        for (const auto& [colour, value] : pov_colors()) names.insert(colour);
        throw SceneError(location_of(node, file),
                         fmt::format("{}: '{}' is neither a vector in [define] nor a colour of POV-Ray's colors.inc{}", what,
                                     name, did_you_mean(name, names)));
    }
    const toml::array* array = node.as_array();
    if (!array || array->size() != 3) {
        std::string got = array ? "an array of " + std::to_string(array->size()) : std::string(type_name(node));
        throw SceneError(location_of(node, file), what + " must be an array of 3 numbers (or a name: a [define] vector, a colour), not " + got);
    }
    dvec3 v;
    for (int i = 0; i < 3; ++i) v[i] = node_number(*array->get(i), file, what + "[" + std::to_string(i) + "]");
    return v;
}

TableReader::TableReader(const toml::table& table, FileName file, std::string what)
    : table_(table), file_(std::move(file)), what_(std::move(what)) {}

bool TableReader::has(std::string_view key) const { return table_.contains(key); }

const toml::node* TableReader::get(std::string_view key, bool required) {
    accept(key);
    const toml::node* node = table_.get(key);
    if (!node && required) throw SceneError(location(), what_ + ": missing required key '" + std::string(key) + "'");
    return node;
}

double TableReader::number(std::string_view key, double fallback) {
    const toml::node* node = get(key, false);
    return node ? node_number(*node, file_, std::string(key)) : fallback;
}

double TableReader::required_number(std::string_view key) {
    return node_number(*get(key, true), file_, std::string(key));
}

int TableReader::integer(std::string_view key, int fallback) {
    const toml::node* node = get(key, false);
    if (!node) return fallback;
    auto i = node->as_integer();
    if (!i) throw SceneError(location_of(*node, file_), std::string(key) + " must be an integer, not " + type_name(*node));
    std::int64_t v = i->get();
    if (v < -2147483647 || v > 2147483647) throw SceneError(location_of(*node, file_), std::string(key) + " is out of range");
    return static_cast<int>(v);
}

dvec3 TableReader::vec3(std::string_view key, dvec3 fallback) {
    const toml::node* node = get(key, false);
    return node ? node_vec3(*node, file_, std::string(key)) : fallback;
}

dvec3 TableReader::required_vec3(std::string_view key) {
    return node_vec3(*get(key, true), file_, std::string(key));
}

std::string node_string(const toml::node& node, const std::string& file, const std::string& what) {
    auto s = node.as_string();
    if (!s) throw SceneError(location_of(node, file), what + " must be a string, not " + type_name(node));
    // TOML allows \u0000; a C string (a file name given to the system) would end there, and
    // silently mean only the part before it.
    const std::string& text = s->get();
    if (std::size_t nul = text.find('\0'); nul != std::string::npos)
        throw SceneError(position_in_string(source_text(file), location_of(node, file), nul),
                         what + " contains a NUL character (\\u0000), which no name or file name can hold");
    return text;
}

std::string TableReader::string(std::string_view key, std::string fallback) {
    const toml::node* node = get(key, false);
    if (!node) return fallback;
    return node_string(*node, file_, std::string(key));
}

std::string TableReader::required_string(std::string_view key) {
    get(key, true);
    return string(key, "");
}

bool TableReader::boolean(std::string_view key, bool fallback) {
    const toml::node* node = get(key, false);
    if (!node) return fallback;
    auto b = node->as_boolean();
    if (!b) throw SceneError(location_of(*node, file_), std::string(key) + " must be true or false, not " + type_name(*node));
    return b->get();
}

const toml::table* TableReader::table(std::string_view key) {
    const toml::node* node = get(key, false);
    if (!node) return nullptr;
    if (!node->is_table()) throw SceneError(location_of(*node, file_), std::string(key) + " must be a table, not " + type_name(*node));
    return node->as_table();
}

const toml::array* TableReader::array(std::string_view key) {
    const toml::node* node = get(key, false);
    if (!node) return nullptr;
    if (!node->is_array()) throw SceneError(location_of(*node, file_), std::string(key) + " must be an array, not " + type_name(*node));
    return node->as_array();
}

const toml::node* TableReader::node(std::string_view key) { return get(key, false); }

void TableReader::accept(std::string_view key) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
}

void TableReader::finish() const {
    for (auto&& [key, value] : table_) {
        if (std::find(known_.begin(), known_.end(), key.str()) != known_.end()) continue;
        // A POV-Ray word's lancer name says more than a spelling close to it.
        std::string suggestion = pov_ray_key_hint(key.str());
        if (suggestion.empty()) suggestion = did_you_mean(key.str(), names_of(known_));
        std::string message = what_ + ": unknown key '" + std::string(key.str()) + "'" + suggestion;
        throw SceneError(location_of(key.source(), file_), message);
    }
}

SourceLocation TableReader::location() const { return location_of(table_, file_); }

SourceLocation TableReader::location(std::string_view key) const {
    if (const toml::node* node = table_.get(key)) return location_of(*node, file_);
    return location();
}

void TableReader::fail(std::string_view key, const std::string& message) const {
    throw SceneError(location(key), message);
}

dvec3 check_color(TableReader& t, std::string_view key, dvec3 c) {
    if (c.r < 0.0 || c.g < 0.0 || c.b < 0.0) t.fail(key, std::string(key) + " components must not be negative");
    return c;
}

double check_range(TableReader& t, std::string_view key, double v, double lo, double hi) {
    if (v < lo || v > hi) t.fail(key, fmt::format("{} must be in [{:g}, {:g}], not {:g}", key, lo, hi, v));
    return v;
}

int check_int_range(TableReader& t, std::string_view key, int v, int lo, int hi) {
    if (v < lo || v > hi) t.fail(key, fmt::format("{} must be between {} and {}, not {}", key, lo, hi, v));
    return v;
}

std::size_t one_of(TableReader& t, std::string_view key, std::string_view what, const std::vector<std::string>& names,
                   const std::string& fallback) {
    std::string value = t.string(key, fallback);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == value) return i;
    std::string listed;  // "a", "b" or "c"
    for (std::size_t i = 0; i < names.size(); ++i)
        listed += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("\"" + names[i] + "\"");
    t.fail(key, fmt::format("unknown {} '{}'", what, value) + did_you_mean(value, names_of(names), " (use " + listed + ")"));
}

}  // namespace lancer
