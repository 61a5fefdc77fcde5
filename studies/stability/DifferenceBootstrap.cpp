#include "studies/stability/DifferenceBootstrap.hpp"

namespace granwave {

std::vector<DifferenceCounts> bootstrapDifferenceCounts(const StabilityGrid& frame,
                                                        const SeedPatterns& s, int resamples) {
  std::vector<DifferenceCounts> out;
  if (s.patterns[0].empty() || s.patterns[0].size() != s.patterns[1].size() || resamples <= 0)
    return out;
  const StabilityGrid full = revoteGrid(frame, s, allSeeds(s), 0);
  const std::size_t NF = frame.frequencies.size();
  // counts[difference][frequency][resample]
  std::vector<std::vector<std::vector<double>>> counts(std::size(kDifferences),
                                                       std::vector<std::vector<double>>(NF));
  const PointDraws draws = pointDraws(s, resamples, 20261202);
  for (std::size_t r = 0; r < static_cast<std::size_t>(resamples); ++r) {
    const StabilityGrid g = revoteGrid(frame, s, draws, r);
    for (std::size_t d = 0; d < std::size(kDifferences); ++d) {
      const std::vector<double> n = g.differencesPerFrequency(kDifferences[d]);
      for (std::size_t i = 0; i < NF; ++i) counts[d][i].push_back(n[i]);
    }
  }
  for (std::size_t d = 0; d < std::size(kDifferences); ++d) {
    DifferenceCounts c;
    c.difference = kDifferences[d];
    c.grid = full.differencesPerFrequency(c.difference);
    for (std::size_t i = 0; i < NF; ++i) c.resampled.push_back(percentileInterval(counts[d][i]));
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace granwave
