#pragma once
// "Did you mean ...?" for names a user typed: the scene loader's keys and types, and the names in
// parametric-surface expressions. In core so that every module can suggest without depending on
// the scene loader.
#include <set>
#include <string>
#include <string_view>

namespace lancer {

// Optimal string alignment distance: insertions, deletions, substitutions and transpositions of
// adjacent letters ("fvo" -> "fov") each cost 1.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word` by edit distance, or "" when nothing is plausibly a typo.
std::string closest_match(std::string_view word, const std::set<std::string, std::less<>>& candidates);

}  // namespace lancer
