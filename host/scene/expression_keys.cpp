#include "scene/expression_keys.hpp"

#include <algorithm>

#include "scene/scene_values.hpp"
#include "scene/string_position.hpp"

namespace lancer {

SourceLocation column_in_string(const toml::node& node, const std::string& file, int column) {
    return position_in_string(source_text(file), location_of(node, file), static_cast<std::size_t>(column));
}

surface::Expr parse_expression_key(const toml::node& node, const std::string& file, const std::string& what,
                                   const surface::Constants& constants, surface::Variables variables) {
    const auto* text = node.as_string();
    if (!text)
        throw SceneError(location_of(node, file),
                         what + " must be a string holding an expression in " + surface::list_variables(variables));
    if (SceneValues* values = current_scene_values()) values->note_expression(text->get());
    try {
        return surface::parse_expression(text->get(), constants, variables);
    } catch (const surface::ExprError& e) {
        throw SceneError(column_in_string(node, file, e.column), e.what());
    } catch (const UserError& e) {
        throw SceneError(location_of(node, file), e.what());
    }
}

surface::Constants read_params(TableReader& t, surface::Variables variables) {
    // The scene's named numbers ([define], clock, frame, repeat indices) first, but not those a
    // variable's name hides; then the surface's own.
    surface::Constants constants;
    if (const SceneValues* values = current_scene_values())
        for (const auto& [name, value] : values->numbers())
            if (std::find(variables.begin(), variables.end(), name) == variables.end()) constants[name] = value;
    const toml::table* params = t.table("params");
    if (!params) return constants;
    for (auto&& [key, node] : *params)
        constants[std::string(key.str())] = node_number(node, t.file(), "params." + std::string(key.str()));
    return constants;
}

}  // namespace lancer
