#include "scene/scene_values.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <regex>
#include <span>
#include <vector>

#include <fmt/format.h>

#include "scene/expression_keys.hpp"
#include "scene/pov_colors.hpp"
#include "scene/toml_reader.hpp"
#include "surface/expr/evaluate.hpp"
#include "surface/expr/functions.hpp"

namespace lancer {
namespace {

thread_local SceneValues* current = nullptr;

bool names_time(const std::string& text) {
    static const std::regex time(R"(\b(clock|frame)\b)");
    return std::regex_search(text, time);
}

bool is_name(std::string_view name) {
    if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
    return std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

}  // namespace

SceneValues::SceneValues(SceneTime time) {
    numbers_["clock"] = time.clock;
    numbers_["frame"] = time.frame;
}

double SceneValues::evaluate(const toml::node& node, const std::string& file, const std::string& what) {
    const std::string& text = node.as_string()->get();
    const surface::Expr expr = parse_expression_key(node, file, what, numbers_, surface::Variables{});
    const double value = surface::evaluate<double>(expr, std::span<const double>{});
    if (!std::isfinite(value))
        throw SceneError(location_of(node, file), fmt::format("{} = \"{}\" is {}: not a finite number", what, text, value));
    return value;
}

std::optional<dvec3> SceneValues::vector(std::string_view name) const {
    if (auto found = vectors_.find(name); found != vectors_.end()) return found->second;
    if (auto colour = pov_colors().find(name); colour != pov_colors().end()) return colour->second;
    return std::nullopt;
}

std::vector<std::string> SceneValues::read_defines(const toml::table& defines, const std::string& file, const std::string& where) {
    std::vector<std::string> names;
    std::vector<std::pair<std::string_view, const toml::node*>> entries;
    for (auto&& [key, node] : defines) entries.emplace_back(key.str(), &node);
    // TOML keeps no order; the file's is the one a reader sees.
    std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
        const auto pa = a.second->source().begin, pb = b.second->source().begin;
        return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
    });
    for (const auto& [key, node] : entries) {
        const std::string name(key), what = where + "." + name;
        check_new_name(name, location_of(*node, file), what);
        if (node->is_array()) vectors_[name] = node_vec3(*node, file, what);
        else numbers_[name] = node_number(*node, file, what);
        names.push_back(name);
    }
    return names;
}

void SceneValues::check_new_name(const std::string& name, const SourceLocation& at, const std::string& what) const {
    if (!is_name(name)) throw SceneError(at, fmt::format("{}: a name is a letter, then letters, digits or _", what));
    if (name == "pi" || name == "e" || surface::find_function(name))
        throw SceneError(at, fmt::format("{}: '{}' is already a name in expressions", what, name));
    if (is_bound(name))  // clock and frame are bound from the start
        throw SceneError(at, fmt::format("{}: '{}' is already a name (clock, frame, a [define], a repeat's index, or an "
                                         "enclosing object's define)", what, name));
}

void SceneValues::note_expression(const std::string& text) { uses_time_ = uses_time_ || names_time(text); }

SceneValues* current_scene_values() { return current; }

SceneValuesScope::SceneValuesScope(SceneValues& values) : previous_(current) { current = &values; }
SceneValuesScope::~SceneValuesScope() { current = previous_; }

}  // namespace lancer
