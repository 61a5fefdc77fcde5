#include "studies/stability/StabilityOverSeedsReport.hpp"

#include <fmt/format.h>

#include <map>

#include "studies/statistics/Measurement.hpp"

namespace granwave {

namespace {

// "3 seeds at 20 points, 5 seeds at 1 point".
std::string seedCountText(const StabilityResults& r) {
  std::map<int, int> points;
  for (double n : r.seeds_per_point) ++points[static_cast<int>(n)];
  std::string text;
  for (auto [seeds, n] : points)
    text += fmt::format(", {} seeds at {} point{}", seeds, n, n == 1 ? "" : "s");
  return text.empty() ? "no seeds" : text.substr(2);
}

}  // namespace

Table featuresTable(const StabilityResults& r) {
  Table t;
  t.title = "Paper against particles";
  t.caption = fmt::format(
      "States are the most frequent over the seeds, with the number of seeds that gave them. "
      "Stability: the share of {} bootstrap resamples of the seeds (drawn with replacement at "
      "each point, voted again) that give the same verdict; near 100 % no choice of seeds "
      "changes it, near 50 % it is a coin flip. A verdict is decided from {:.0f} % on. While one "
      "is not, the study adds [particles] seed_step seeds at every point whose seeds disagree, "
      "up to max_seeds = {} there (this run: {}); a verdict still short then is undecided.",
      r.bootstrap.resamples, 100 * kDecidedAgreement, r.max_seeds, seedCountText(r));
  t.columns = {"feature (paper)", "particles (this grid)", "reproduced", "stability over seeds"};
  for (const FeatureCheck& c : r.features) {
    const auto it = r.bootstrap.verdict_agreement.find(c.key);
    t.rows.push_back(
        {c.feature, c.observed, c.verdict,
         it == r.bootstrap.verdict_agreement.end()
             ? std::string("–")
             : fmt::format("{:.0f} % ({})", 100 * it->second,
                           it->second >= kDecidedAgreement ? "decided" : "undecided")});
  }
  return t;
}

// The dry-wet difference counts per frequency, by the paper's symbol and in any of them, with
// their median and 95 % interval over the seed resamples.
Table differencesTable(const StabilityResults& r) {
  Table t;
  t.title = "Dry-wet differences per frequency, by symbol, over seed resamples";
  const int resamples = r.difference_counts.empty() || r.difference_counts[0].resampled.empty()
                            ? 0
                            : r.difference_counts[0].resampled[0].resamples;
  t.caption = fmt::format(
      "Gamma points where dry and wet differ in the state (by each solid criterion), in surface "
      "waves, in kinks, and in any of the paper's symbols: the count on the grid (most frequent "
      "verdicts), then in brackets its median and 95 % interval over {} bootstrap resamples "
      "of the seeds (drawn with replacement at each point, voted again). A zero-width interval: "
      "no choice of seeds changes the count.",
      resamples);
  t.columns = {"f (Hz)"};
  for (const DifferenceCounts& c : r.difference_counts)
    t.columns.push_back(differenceName(c.difference));
  for (std::size_t i = 0; i < r.grid.frequencies.size(); ++i) {
    std::vector<std::string> row{formatCompact(r.grid.frequencies[i])};
    for (const DifferenceCounts& c : r.difference_counts) {
      const PercentileInterval& p = c.resampled[i];
      row.push_back(fmt::format("{} ({}; {}–{})", formatCompact(c.grid[i]), formatCompact(p.median),
                                formatCompact(p.low), formatCompact(p.high)));
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace granwave
