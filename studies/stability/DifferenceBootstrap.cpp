#include "studies/stability/DifferenceBootstrap.hpp"

namespace granwave {

namespace {

// The grid voted again, point p from the seeds draws[first + p].
StabilityGrid revote(const StabilityGrid& frame, const SeedPatterns& s,
                     const std::vector<std::vector<std::size_t>>& draws, std::size_t first) {
  StabilityGrid g;
  g.frequencies = frame.frequencies;
  g.gammas = frame.gammas;
  for (int law = 0; law < 2; ++law)
    for (std::size_t p = 0; p < s.patterns[law].size(); ++p)
      g.verdicts[law].push_back(revotePoint(s, law, p, draws[first + p]));
  return g;
}

std::size_t seedCount(const SeedPatterns& s) {
  return s.patterns[0].empty() ? 0 : s.patterns[0].front().size();
}

}  // namespace

std::vector<DifferenceCounts> bootstrapDifferenceCounts(const StabilityGrid& frame,
                                                        const SeedPatterns& s, int resamples) {
  const std::size_t seeds = seedCount(s), points = s.patterns[0].size();
  std::vector<DifferenceCounts> out;
  if (seeds == 0 || points != s.patterns[1].size()) return out;
  std::vector<std::vector<std::size_t>> all(points, std::vector<std::size_t>(seeds));
  for (auto& d : all)
    for (std::size_t k = 0; k < seeds; ++k) d[k] = k;
  const StabilityGrid full = revote(frame, s, all, 0);
  const std::size_t NF = frame.frequencies.size();
  // counts[difference][frequency][resample]
  std::vector<std::vector<std::vector<double>>> counts(std::size(kDifferences),
                                                       std::vector<std::vector<double>>(NF));
  const auto draws = seedDraws(seeds, resamples * static_cast<int>(points), 20261202);
  for (int r = 0; r < resamples; ++r) {
    const StabilityGrid g = revote(frame, s, draws, static_cast<std::size_t>(r) * points);
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
