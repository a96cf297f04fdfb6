// "Did you mean ...?" for a mistyped command or option name: the closest
// valid name by edit distance. CLI11 2.1 (Debian 12's) has no suggestions of
// its own. Part of m3g_cli_support; pure functions, unit-tested.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace m3gcli {

/// Optimal-string-alignment distance: insertions, deletions, substitutions
/// and transpositions of neighbours ("szie" -> "size" is 1) each cost 1.
std::size_t editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word`, if it is close enough to be what was
/// meant: at most max(2, length / 3) edits away, or `word` (3 characters or
/// more) is the start of exactly one candidate. Leading dashes are ignored
/// when measuring ("--szie" against "--size"); an "=value" on `word` is
/// dropped. Ties go to the earlier candidate.
std::optional<std::string> closestName(std::string_view word, std::span<const std::string> candidates);

}  // namespace m3gcli
