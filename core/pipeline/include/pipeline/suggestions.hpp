#pragma once
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <string_view>
#include <vector>

// "Did you mean" for names a user mistyped: keys, node ids, node types, choices.
// Not part of the SDK: exported from libstrata_core for Strata's own tests and tools.
STRATA_EXPORTS_BEGIN
namespace strata::loader {

// Edits (insert, delete, substitute, swap two neighbours) that turn one word into the other, ignoring
// case: the optimal string alignment distance.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to `word` when it is near enough to be what the user meant: at most one edit
// per three letters of `word` (at least one). Ties go to the earlier candidate.
std::optional<std::string> closestMatch(std::string_view word, const std::vector<std::string>& candidates);

// "; did you mean 'camera'?" when a candidate is close, "" otherwise: appended to a problem text.
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

// 'a', 'b', 'c': names for a message.
std::string quotedList(const std::vector<std::string>& names);

}  // namespace strata::loader
STRATA_EXPORTS_END
