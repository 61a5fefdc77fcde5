#include "studies/stability/SeedBootstrap.hpp"

#include "studies/framework/SeedResampling.hpp"
#include "studies/stability/StabilityFeatures.hpp"

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

namespace {

// The grid voted again from the seeds `draw` (indices into each point's seeds).
StabilityGrid revote(const StabilityGrid& grid, const SeedPatterns& s,
                     const std::vector<std::size_t>& draw) {
  StabilityGrid g;
  g.frequencies = grid.frequencies;
  g.gammas = grid.gammas;
  for (int law = 0; law < 2; ++law)
    for (std::size_t p = 0; p < s.patterns[law].size(); ++p) {
      g.verdicts[law].push_back(revotePoint(s, law, p, draw));
    }
  return g;
}

}  // namespace

SeedBootstrap bootstrapOverSeeds(const StabilityGrid& grid, const SeedPatterns& s, int resamples) {
  SeedBootstrap b;
  b.resamples = resamples;
  const std::size_t seeds =
      s.patterns[0].empty() || s.patterns[0].front().empty() ? 0 : s.patterns[0].front().size();
  if (seeds == 0 || resamples <= 0) return b;
  std::vector<std::size_t> all(seeds);
  for (std::size_t k = 0; k < seeds; ++k) all[k] = k;
  std::map<std::string, std::string> reference;
  for (const FeatureCheck& c : checkPaperFeatures(revote(grid, s, all)))
    reference[c.key] = c.verdict;

  for (const auto& draw : seedDraws(seeds, resamples, 20150415)) {
    const StabilityGrid g = revote(grid, s, draw);
    for (const FeatureCheck& c : checkPaperFeatures(g))
      b.verdict_agreement[c.key] += c.verdict == reference[c.key] ? 1.0 : 0.0;
  }
  for (const auto& [key, verdict] : reference) b.verdict_agreement.try_emplace(key, 0.0);
  for (auto& [key, agreeing] : b.verdict_agreement) agreeing /= resamples;
  return b;
}

}  // namespace granwave
