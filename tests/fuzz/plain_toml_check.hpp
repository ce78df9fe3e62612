#pragma once
// The plain TOML reader (scene/plain_toml.hpp) must give toml::parse's very tree wherever it
// answers: the scene fuzz target checks so on every input, the whole text and each batch of it.
#include <string>
#include <string_view>

namespace lancer::fuzz {

// Throws InvariantBroken (fuzz_entries.hpp) where the plain reader answers for `text`, or for a
// batch of its [[object]] tables (split_object_tables, one table a batch), with a tree that
// differs from toml::parse's, or where toml::parse refuses what it read.
void check_plain_toml(std::string_view text, const std::string& path);

}  // namespace lancer::fuzz
