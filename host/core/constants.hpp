#pragma once
// Mathematical constants every module uses, defined once.
#include <numbers>

namespace lancer {

inline constexpr double kPi = std::numbers::pi;

}  // namespace lancer
