#pragma once
// Keys that hold expressions (parametric and implicit surfaces): a TOML string parsed in the
// surface's variables, with every error at its exact column inside the string, and the named
// constants of `params = { R = 1, r = 0.35 }`.
#include <string>

#include "scene/toml_reader.hpp"
#include "surface/expr/parser.hpp"

namespace lancer {

// Where byte `column` (0-based) of a TOML string value's text is in the file.
SourceLocation column_in_string(const toml::node& node, const std::string& file, int column);

// The expression in the string `node`; `what` names the key in messages.
surface::Expr parse_expression_key(const toml::node& node, const std::string& file, const std::string& what,
                                   const surface::Constants& constants,
                                   surface::Variables variables = surface::kParametricVariables);

// The named constants a surface's expressions in `variables` see: the scene's named numbers
// (scene_values.hpp) that no variable hides, and its table `params` (empty when absent).
surface::Constants read_params(TableReader& t, surface::Variables variables);

}  // namespace lancer
