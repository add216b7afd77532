#pragma once
// "Did you mean …?" for a name the user misspelt (an option, a command, a model, a material):
// the closest known name by edit distance, when it is close enough to be a likely typo.

#include <string>
#include <string_view>
#include <vector>

namespace bounce {

/// The optimal-string-alignment distance of a and b: insertions, deletions, substitutions
/// and transpositions of two neighbouring characters, each counting 1 ("velocty" ->
/// "velocity" is 1, "kirjt" -> "krijt" is 1).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The known name closest to `typed`, or "" when none is a likely typo: a name at most
/// max(1, min(3, length / 4)) edits away (ties go to the first in `names`), or else the
/// only name that `typed` (3 characters or more) begins. Case is ignored.
std::string closest_name(std::string_view typed, const std::vector<std::string>& names);

/// "; did you mean X?" for the end of a message, or "" when there is no likely name.
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& names);

}  // namespace bounce
