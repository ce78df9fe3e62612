#pragma once
// Numbers by name and by rule in a scene file (docs/scene-format.md, "Numbers, names and
// loops"), as POV-Ray's #declare, clock and #for: any number may be an expression (a string) of
// the scene's [define] values, `clock` (0 to 1 over an animation), `frame` and the indices of
// the `repeat`s around it; any 3-vector may name a [define] vector or a colour of POV-Ray's
// colors.inc. The loader holds one SceneValues while it reads a file (SceneValuesScope), and
// node_number / node_vec3 (toml_reader.hpp) consult it.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "scene/scene.hpp"
#include "surface/expr/parser.hpp"

namespace lancer {

// The moment a scene is read at: clock from 0 to 1 over an animation's frames (frame_time), and
// the frame's number from 0. A still is read at frame 0, clock 0.
struct SceneTime {
    double clock = 0.0;
    int frame = 0;
};

class SceneValues {
public:
    explicit SceneValues(SceneTime time);

    // The value of the expression in the string `node`; `what` names it in messages.
    double evaluate(const toml::node& node, const std::string& file, const std::string& what);
    // The vector a string names: a [define] vector, else a colors.inc colour.
    std::optional<dvec3> vector(std::string_view name) const;

    // [define], or an object's own `define` (read for each copy of a repeat): each entry in the
    // file's order, so that one may use those above it. Returns the names, for unbind.
    std::vector<std::string> read_defines(const toml::table& defines, const std::string& file, const std::string& where = "define");

    // Fails at `at` unless `name` may name a new value: a name, and none an expression knows yet
    // (a function, pi, e, clock, frame, a [define], a repeat's index, an enclosing define).
    void check_new_name(const std::string& name, const SourceLocation& at, const std::string& what) const;
    // A repeat's index, visible to the expressions read until it is taken away.
    void bind(const std::string& name, double value) { numbers_[name] = value; }
    void unbind(const std::string& name) {
        numbers_.erase(name);
        vectors_.erase(name);
    }
    bool is_bound(std::string_view name) const { return numbers_.count(name) != 0 || vectors_.count(name) != 0; }

    // The named numbers (defines, clock, frame, indices), for surfaces' expressions as constants.
    const surface::Constants& numbers() const { return numbers_; }
    // Whether any expression read so far named clock or frame (the scene is then read again for
    // each frame); parse_expression_key notes each.
    void note_expression(const std::string& text);
    bool uses_time() const { return uses_time_; }

private:
    surface::Constants numbers_;
    std::map<std::string, dvec3, std::less<>> vectors_;
    bool uses_time_ = false;
};

// The values of the file being read, or none (outside a load: expressions are then errors).
SceneValues* current_scene_values();

// Makes `values` current for its lifetime (a load, on this thread).
class SceneValuesScope {
public:
    explicit SceneValuesScope(SceneValues& values);
    ~SceneValuesScope();
    SceneValuesScope(const SceneValuesScope&) = delete;
    SceneValuesScope& operator=(const SceneValuesScope&) = delete;

private:
    SceneValues* previous_;
};

}  // namespace lancer
