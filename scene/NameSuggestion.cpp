#include "scene/NameSuggestion.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace granwave {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

std::optional<std::string> closestName(std::string_view word,
                                       const std::vector<std::string>& valid) {
  const std::string* best = nullptr;
  std::size_t best_distance = 4;
  for (const auto& c : valid) {
    const std::size_t d = editDistance(word, c);
    if (d < best_distance) best = &c, best_distance = d;
  }
  if (!best) return std::nullopt;
  return *best;
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& valid) {
  const auto best = closestName(word, valid);
  return best ? fmt::format(" (did you mean '{}'?)", *best) : "";
}

}  // namespace granwave
