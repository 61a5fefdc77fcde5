#include "studies/momentum_transfer/BinaryImpactEstimate.hpp"

#include <fmt/format.h>

#include <limits>
#include <optional>

#include "particles/EdSimulation.hpp"
#include "particles/H5mdLayout.hpp"
#include "particles/PairImpactHistogram.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

double lawRatioOverImpacts(const ImpactSpeedCounts& h, const Restitution& dry,
                           const Restitution& wet) {
  const double width = h.speed_max / static_cast<double>(h.counts.size());
  double sum = 0, n = 0;
  for (std::size_t k = 0; k < h.counts.size(); ++k) {
    if (h.counts[k] == 0) continue;
    const double v = (static_cast<double>(k) + 0.5) * width;
    const double c = static_cast<double>(h.counts[k]);
    sum += c * (1 + dry(v)) / (1 + wet(v));
    n += c;
  }
  return n > 0 ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

namespace {

// The run's impacts in the wave window, or why there are none.
std::optional<ImpactSpeedCounts> windowImpacts(const std::string& run_path,
                                               const std::vector<bool>& wave, std::string& why) {
  const h5::File f = h5::File::openReadOnly(run_path);
  if (!f.exists(h5md::kPairImpacts)) {
    why = run_path + " has no pair-impact histogram (a run file of an older granwave)";
    return std::nullopt;
  }
  const PairImpactHistogram h = PairImpactHistogram::read(f, h5md::kPairImpacts);
  if (static_cast<std::size_t>(h.bins().phase_bins) != wave.size()) {
    why = fmt::format("{}: {} phase bins of pair impacts, {} phases of fields", run_path,
                      h.bins().phase_bins, wave.size());
    return std::nullopt;
  }
  return ImpactSpeedCounts{h.bins().speed_max, h.speedCounts(wave)};
}

ImpactSpeedCounts pooled(const std::vector<SeedImpacts>& seeds,
                         const std::vector<std::size_t>& draw, int law) {
  ImpactSpeedCounts sum{seeds.front().law[law].speed_max,
                        std::vector<std::uint64_t>(seeds.front().law[law].counts.size(), 0)};
  for (std::size_t i : draw)
    for (std::size_t k = 0; k < sum.counts.size(); ++k)
      sum.counts[k] += seeds[i].law[law].counts[k];
  return sum;
}

double shareBelow(const ImpactSpeedCounts& h, double speed) {
  double below = 0, n = 0;
  const double width = h.speed_max / static_cast<double>(h.counts.size());
  for (std::size_t k = 0; k < h.counts.size(); ++k) {
    n += static_cast<double>(h.counts[k]);
    if ((static_cast<double>(k) + 0.5) * width < speed) below += static_cast<double>(h.counts[k]);
  }
  return n > 0 ? below / n : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

BinaryImpactEstimate binaryImpactEstimate(const MomentumTransferConfig& c, const RunSet& runs,
                                          const std::vector<int>& seeds,
                                          const std::vector<std::vector<bool>>& wave,
                                          int resamples) {
  BinaryImpactEstimate e;
  for (std::size_t i = 0; i < seeds.size() && e.missing.empty(); ++i) {
    SeedImpacts s{seeds[i], {}};
    for (int law = 0; law < kLaws && e.missing.empty(); ++law) {
      const RunRecord& r = runs.get(MomentumTransferConfig::label(law, seeds[i]));
      const auto counts = windowImpacts(r.runPath(), wave[i], e.missing);
      if (counts) s.law[law] = *counts;
    }
    e.seeds.push_back(std::move(s));
  }
  if (e.seeds.empty() && e.missing.empty()) e.missing = "no seed has both runs";
  if (!e.missing.empty()) return e;
  const Restitution dry = engineConfig(c.scenes.base[0]).restitution;
  const Restitution wet = engineConfig(c.scenes.base[1]).restitution;
  e.onset_speed = wet.onsetVelocity();
  std::vector<std::size_t> all(e.seeds.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  const auto draws = seedDraws(e.seeds.size(), resamples, 20151001);
  for (int law = 0; law < kLaws; ++law) {
    for (const SeedImpacts& s : e.seeds)
      e.per_seed[law].push_back(lawRatioOverImpacts(s.law[law], dry, wet));
    const ImpactSpeedCounts every = pooled(e.seeds, all, law);
    e.pooled[law] = lawRatioOverImpacts(every, dry, wet);
    for (std::uint64_t n : every.counts) e.impacts[law] += n;
    e.below_onset[law] = shareBelow(every, e.onset_speed);
    std::vector<double> values;
    for (const auto& draw : draws)
      values.push_back(lawRatioOverImpacts(pooled(e.seeds, draw, law), dry, wet));
    e.bootstrap[law] = percentileInterval(std::move(values));
  }
  return e;
}

void writeBinaryImpactEstimate(h5::File& f, const std::string& group,
                               const BinaryImpactEstimate& e) {
  const std::string g = group + "/binary_impact";
  f.createGroup(g);
  if (!e.missing.empty()) {
    f.writeStringAttribute(g, "missing", e.missing);
    return;
  }
  for (int law = 0; law < kLaws; ++law) {
    const std::string n = fmt::format("_{}_impacts", kLawNames[law]);
    putValue(f, g, "ratio" + n, e.pooled[law]);
    putValue(f, g, "ratio_median" + n, e.bootstrap[law].median);
    putValue(f, g, "ratio_low95" + n, e.bootstrap[law].low);
    putValue(f, g, "ratio_high95" + n, e.bootstrap[law].high);
    putValue(f, g, "impacts" + n, static_cast<double>(e.impacts[law]));
    putValue(f, g, "share_below_wet_onset" + n, e.below_onset[law]);
    putSeries(f, g + "/ratio_per_seed" + n, e.per_seed[law], "1");
  }
  std::vector<double> seeds;
  for (const SeedImpacts& s : e.seeds) seeds.push_back(s.seed);
  putSeries(f, g + "/seeds", seeds, "1");
  putValue(f, g, "resamples", static_cast<double>(e.bootstrap[1].resamples));
  putValue(f, g, "wet_onset_speed", e.onset_speed);
  putValue(f, g, "binary_estimate", 2.0);
}

}  // namespace granwave
