#include "fuzz/plain_toml_check.hpp"

#include <optional>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "fuzz/fuzz_entries.hpp"
#include "fuzz/toml_tree_difference.hpp"
#include "scene/object_batches.hpp"
#include "scene/plain_toml.hpp"

namespace lancer::fuzz {
namespace {

void check_plain_toml_part(std::string_view text, const std::string& path, const std::string& what) {
    const std::optional<toml::table> plain = parse_plain_toml(text, path);
    if (!plain) return;
    toml::table parsed;
    try {
        parsed = toml::parse(text, std::string_view(path));
    } catch (const toml::parse_error& e) {
        throw InvariantBroken(fmt::format("{}: the plain TOML reader read what toml::parse refuses ({})", what, e.description()));
    }
    if (const std::string difference = toml_tree_difference(parsed, *plain); !difference.empty())
        throw InvariantBroken(fmt::format("{}: the plain TOML reader's tree differs from toml::parse's: {}", what, difference));
}

}  // namespace

void check_plain_toml(std::string_view text, const std::string& path) {
    check_plain_toml_part(text, path, "the whole text");
    const std::optional<SceneTextParts> parts = split_object_tables(text, 1);
    if (!parts) return;
    for (const ObjectBatch& b : parts->batches)
        check_plain_toml_part(text.substr(b.begin, b.end - b.begin), path, fmt::format("the batch from line {}", b.first_line));
}

}  // namespace lancer::fuzz
