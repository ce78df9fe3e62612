#pragma once
namespace lancer {
inline constexpr const char* kVersion = "0.1.0";
}
