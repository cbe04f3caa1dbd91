#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace argus::config {

/// Number of single-character insertions, deletions, substitutions and swaps of adjacent
/// characters that turn `from` into `to` (optimal string alignment distance). Swaps count
/// once because "sede" for "seed" is one slip of the fingers, not two.
std::size_t edit_distance(std::string_view from, std::string_view to);

/// The candidate closest to `word`, if it is at most `max_distance` edits away; the first
/// one wins a tie. Used for "did you mean ...?" hints.
std::optional<std::string_view> closest_match(std::string_view word,
                                              std::span<const std::string_view> candidates,
                                              std::size_t max_distance = 2);

}  // namespace argus::config
