#pragma once
// "Did you mean ...?" for a misspelt name: the closest of the valid names by edit distance
// (insertions, deletions, substitutions), if it is within three edits. Used for scene keys
// and sections here, and by the program for commands and options.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace granwave {

std::size_t editDistance(std::string_view a, std::string_view b);

// The valid name closest to `word` within three edits (the first of equally close ones).
std::optional<std::string> closestName(std::string_view word,
                                       const std::vector<std::string>& valid);

// " (did you mean 'drive.gamma'?)" for the closest valid name, or "".
std::string didYouMean(std::string_view word, const std::vector<std::string>& valid);

}  // namespace granwave
