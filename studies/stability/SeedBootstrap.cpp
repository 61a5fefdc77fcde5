#include "studies/stability/SeedBootstrap.hpp"

#include "studies/stability/StabilityFeatures.hpp"
#include "studies/statistics/SeedResampling.hpp"

namespace granwave {

LayerVerdict revotePoint(const SeedPatterns& s, int law, std::size_t p,
                         const std::vector<std::size_t>& draw) {
  std::vector<LayerPatterns> patterns;
  std::vector<bool> finished;
  std::vector<std::string> messages;
  for (std::size_t k : draw) {
    patterns.push_back(s.patterns[law][p][k]);
    finished.push_back(s.finished[law][p][k]);
    messages.push_back(s.messages[law][p][k]);
  }
  return voteOverSeeds(patterns, finished, messages);
}

PointDraws pointDraws(const SeedPatterns& s, int resamples, std::uint64_t rng_seed) {
  PointDraws out;
  for (std::size_t p = 0; p < s.patterns[0].size(); ++p)
    out.push_back(seedDraws(s.patterns[0][p].size(), resamples, rng_seed + p));
  return out;
}

PointDraws allSeeds(const SeedPatterns& s) {
  PointDraws out;
  for (const auto& point : s.patterns[0]) {
    std::vector<std::size_t> all(point.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
    out.push_back({all});
  }
  return out;
}

StabilityGrid revoteGrid(const StabilityGrid& frame, const SeedPatterns& s, const PointDraws& draws,
                         std::size_t r) {
  StabilityGrid g;
  g.frequencies = frame.frequencies;
  g.gammas = frame.gammas;
  for (int law = 0; law < 2; ++law)
    for (std::size_t p = 0; p < s.patterns[law].size(); ++p)
      g.verdicts[law].push_back(revotePoint(s, law, p, draws[p][r]));
  return g;
}

SeedBootstrap bootstrapOverSeeds(const StabilityGrid& grid, const SeedPatterns& s, int resamples) {
  SeedBootstrap b;
  b.resamples = resamples;
  if (s.patterns[0].empty() || s.patterns[0].size() != s.patterns[1].size() || resamples <= 0)
    return b;
  std::map<std::string, std::string> reference;
  for (const FeatureCheck& c : checkPaperFeatures(revoteGrid(grid, s, allSeeds(s), 0)))
    reference[c.key] = c.verdict;
  const PointDraws draws = pointDraws(s, resamples, 20150415);
  for (std::size_t r = 0; r < static_cast<std::size_t>(resamples); ++r)
    for (const FeatureCheck& c : checkPaperFeatures(revoteGrid(grid, s, draws, r)))
      b.verdict_agreement[c.key] += c.verdict == reference[c.key] ? 1.0 : 0.0;
  for (const auto& [key, verdict] : reference) b.verdict_agreement.try_emplace(key, 0.0);
  for (auto& [key, agreeing] : b.verdict_agreement) agreeing /= resamples;
  return b;
}

}  // namespace granwave
