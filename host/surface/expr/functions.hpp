#pragma once
// The functions expressions may call: the one table the parser, its error messages and the
// documentation are written from.
#include <span>
#include <string_view>

#include "surface/expr/expr.hpp"

namespace lancer::surface {

struct FunctionInfo {
    std::string_view name;
    int arity;
    Op op;
    std::string_view meaning;
};

std::span<const FunctionInfo> function_table();
const FunctionInfo* find_function(std::string_view name);  // nullptr when there is none
std::string_view function_name(Op op);                     // "" for operators

}  // namespace lancer::surface
