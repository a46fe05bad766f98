#pragma once
// "did you mean `x`?" for a misspelt name (deck keys, channel names, scene keys): the closest
// candidate within an edit distance of max(2, length / 3), or the candidate the written name is a
// prefix of up to a `_unit` suffix (`blade_pitch` for `blade_pitch_deg`). Channel names compare
// without case (OpenFAST's are case-insensitive); deck keys with it.
#include <string>
#include <string_view>
#include <vector>

namespace fowtsim::io {

enum class LetterCase { matters, ignored };

// The closest candidate, or "" when none is close enough to be a typo.
std::string closest_name(std::string_view written, const std::vector<std::string>& candidates,
                         LetterCase letter_case = LetterCase::matters);

// "did you mean `x`?", or "".
std::string did_you_mean(std::string_view written, const std::vector<std::string>& candidates,
                         LetterCase letter_case = LetterCase::matters);

}  // namespace fowtsim::io
