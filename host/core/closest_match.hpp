#pragma once
// "Did you mean ...?" for names a user typed: the scene loader's keys and types, and the names in
// parametric-surface expressions. In core so that every module can suggest without depending on
// the scene loader.
#include <set>
#include <string>
#include <string_view>
#include <type_traits>

namespace lancer {

// Optimal string alignment distance: insertions, deletions, substitutions and transpositions of
// adjacent letters ("fvo" -> "fov") each cost 1.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word` by edit distance, or "" when nothing is plausibly a typo.
std::string closest_match(std::string_view word, const std::set<std::string, std::less<>>& candidates);

// The end of an "unknown name" message: " (did you mean 'clamp'?)" when a candidate is close to
// `word`, else `otherwise` (a list of what is allowed, or a hint; may be empty).
std::string did_you_mean(std::string_view word, const std::set<std::string, std::less<>>& candidates,
                         std::string_view otherwise = "");

// The keys of a map (or the strings of any range of strings), as candidates for did_you_mean.
template <typename Range>
std::set<std::string, std::less<>> names_of(const Range& range) {
    std::set<std::string, std::less<>> names;
    for (const auto& element : range) {
        if constexpr (std::is_convertible_v<decltype(element), std::string_view>) names.emplace(element);
        else names.emplace(element.first);
    }
    return names;
}

}  // namespace lancer
