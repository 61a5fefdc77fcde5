#include "studies/stability/StabilityAnalysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "studies/contract/StudyResults.hpp"
#include "studies/run_files/HydroRunFile.hpp"

namespace granwave {

std::vector<int> seedsAt(const StabilityConfig& c, const RunSet& runs, double fr, double gamma) {
  std::vector<int> seeds = c.seeds;
  for (int sd : c.extraSeeds())
    if (runs.has(StabilityConfig::particleRun(0, fr, gamma, sd))) seeds.push_back(sd);
  return seeds;
}

StabilityGrid voteGrid(const StabilityConfig& c, const RunSet& runs, SeedPatterns& seeds) {
  StabilityGrid grid;
  grid.frequencies = c.frequencies;
  grid.gammas = c.gammas;
  for (int law = 0; law < kLaws; ++law)
    for (double fr : c.frequencies)
      for (double gamma : c.gammas) {
        std::vector<LayerPatterns> patterns;
        std::vector<bool> finished;
        std::vector<std::string> messages;
        for (int seed : seedsAt(c, runs, fr, gamma)) {
          const RunRecord& r = runs.get(StabilityConfig::particleRun(law, fr, gamma, seed));
          patterns.push_back(r.ok ? readLayerPatterns(r.fieldsPath()) : LayerPatterns{});
          finished.push_back(r.ok);
          messages.push_back(r.message);
        }
        grid.verdicts[law].push_back(voteOverSeeds(patterns, finished, messages));
        seeds.patterns[law].push_back(std::move(patterns));
        seeds.finished[law].push_back(std::move(finished));
        seeds.messages[law].push_back(std::move(messages));
      }
  return grid;
}

namespace {

const std::string kRoot = "/results/stability";

HydroPoint hydroPoint(const StabilityConfig& c, const RunSet& runs, int law, double fr,
                      double gamma, bool rough) {
  HydroPoint h;
  if (!(rough ? c.hydro_rough : c.hydro)) return h;
  h.run = true;
  const RunRecord& r = runs.get(StabilityConfig::hydroRun(law, fr, gamma, rough));
  h.ok = r.ok;
  if (!r.ok) {
    h.failure = r.message;
    return h;
  }
  const HydroRunContent hf = readHydroRunFile(r.hydroPath());
  h.periodic = hf.periodic;
  h.period = static_cast<int>(hf.period);
  h.regime = hf.regime;
  return h;
}

// The first seed at the point whose run has `state`, with its last recorded frame.
std::optional<GallerySnapshot> snapshot(const StabilityConfig& c, const RunSet& runs,
                                        std::size_t state, int law, std::size_t i, std::size_t j) {
  for (int seed : c.seeds) {
    const RunRecord& r =
        runs.get(StabilityConfig::particleRun(law, c.frequencies[i], c.gammas[j], seed));
    if (!r.ok) continue;
    GallerySnapshot s;
    s.state = state;
    s.law = law;
    s.seed = seed;
    s.frequency = c.frequencies[i];
    s.gamma = c.gammas[j];
    s.patterns = readLayerPatterns(r.fieldsPath());
    if (!(s.patterns.available && s.patterns.state == kLayerStates[state])) continue;
    const Frame fr = readLastFrame(r.runPath());
    const double d = r.request.scene.particles.diameter;
    for (std::size_t k = 0; k < fr.x.size(); ++k) {
      s.x.push_back(fr.x[k] / d);
      s.z.push_back(fr.z[k] / d);
    }
    s.plate = fr.plate / d;
    s.width = r.request.scene.container.width / d;
    return s;
  }
  return std::nullopt;
}

// A few runs per state: at the points (law, f, Gamma in order) whose verdict is the state.
std::vector<GallerySnapshot> gallery(const StabilityConfig& c, const RunSet& runs,
                                     const StabilityGrid& grid) {
  std::vector<GallerySnapshot> out;
  for (std::size_t si = 0; si < kLayerStates.size(); ++si) {
    int shown = 0;
    for (int law = 0; law < kLaws; ++law)
      for (std::size_t p = 0; p < grid.verdicts[law].size(); ++p) {
        const std::size_t i = p / c.gammas.size(), j = p % c.gammas.size();
        const LayerVerdict& v = grid.at(law, i, j);
        if (shown >= c.gallery_per_state || !v.classified() || v.state.value != kLayerStates[si])
          continue;
        if (auto s = snapshot(c, runs, si, law, i, j)) {
          out.push_back(std::move(*s));
          ++shown;
        }
      }
  }
  return out;
}

// The hydro period of every point: NaN where it failed or was not run, 0 with no period.
std::vector<double> hydroPeriods(const std::vector<HydroPoint>& hydro) {
  std::vector<double> out;
  for (const HydroPoint& h : hydro) out.push_back(h.ok ? (h.periodic ? h.period : 0) : NAN);
  return out;
}

double stateCode(const Vote<std::string>& v) {
  const auto it = std::find(kLayerStates.begin(), kLayerStates.end(), v.value);
  return v.of > 0 && it != kLayerStates.end() ? static_cast<double>(it - kLayerStates.begin())
                                              : NAN;
}

// The within-cycle criterion's numbers per point (the bond criterion's are in writeLaw).
void writeWithinCycle(h5::File& f, const std::string& grp,
                      const std::vector<LayerVerdict>& verdicts) {
  std::vector<double> state, votes, coordination, psi6, lid;
  for (const LayerVerdict& v : verdicts) {
    state.push_back(stateCode(v.within_cycle_state));
    votes.push_back(v.within_cycle_state.count);
    coordination.push_back(v.classified() ? v.within_cycle_coordination : NAN);
    psi6.push_back(v.classified() ? v.within_cycle_psi6 : NAN);
    lid.push_back(v.classified() ? v.lid_row : NAN);
  }
  putSeries(f, grp + "/within_cycle_state", state, "1");
  putSeries(f, grp + "/within_cycle_state_votes", votes, "1");
  putSeries(f, grp + "/within_cycle_coordination", coordination, "1");
  putSeries(f, grp + "/within_cycle_psi6", psi6, "1");
  putSeries(f, grp + "/lid_row", lid, "1");
}

void writeLaw(h5::File& f, const std::string& grp, const std::vector<LayerVerdict>& verdicts,
              const std::vector<HydroPoint>& hydro, const std::vector<HydroPoint>& rough) {
  std::vector<double> state, state_votes, classified, period, period_votes, wave, wave_votes, kinks,
      kinks_votes, agree;
  for (const LayerVerdict& v : verdicts) {
    const bool c = v.classified();
    state.push_back(stateCode(v.state));
    state_votes.push_back(v.state.count);
    classified.push_back(v.state.of);
    period.push_back(v.period.of > 0 ? v.period.value : NAN);
    period_votes.push_back(v.period.count);
    wave.push_back(c ? v.surface_wave.value : NAN);
    wave_votes.push_back(v.surface_wave.count);
    kinks.push_back(c ? v.kinks.value : NAN);
    kinks_votes.push_back(v.kinks.count);
    agree.push_back(v.seedsAgree());
  }
  f.createGroup(grp);
  f.writeStringAttribute(grp, "state_codes", "0 crystal, 1 amorphous, 2 liquid-like");
  f.writeStringAttribute(grp, "layout",
                         "[frequency][gamma], row-major; most frequent over the seeds, "
                         "*_votes: seeds that gave it, classified_seeds: seeds that voted");
  putSeries(f, grp + "/state", state, "1");
  putSeries(f, grp + "/state_votes", state_votes, "1");
  putSeries(f, grp + "/classified_seeds", classified, "1");
  putSeries(f, grp + "/period", period, "1");
  putSeries(f, grp + "/period_votes", period_votes, "1");
  putSeries(f, grp + "/surface_wave", wave, "1");
  putSeries(f, grp + "/surface_wave_votes", wave_votes, "1");
  putSeries(f, grp + "/kinks", kinks, "1");
  putSeries(f, grp + "/kinks_votes", kinks_votes, "1");
  putSeries(f, grp + "/seeds_agree", agree, "1");
  putSeries(f, grp + "/hydro_period", hydroPeriods(hydro), "1");
  putSeries(f, grp + "/hydro_rough_period", hydroPeriods(rough), "1");
  writeWithinCycle(f, grp, verdicts);
}

// Per difference: the count per frequency on the grid and the median and 95 % interval over
// the resamples.
void writeDifferenceCounts(h5::File& f, const std::string& group,
                           const std::vector<DifferenceCounts>& counts) {
  f.createGroup(group);
  for (const DifferenceCounts& c : counts) {
    const std::string g = group + "/" + differenceKey(c.difference);
    f.createGroup(g);
    f.writeAttribute<std::int64_t>(g, "resamples",
                                   c.resampled.empty() ? 0 : c.resampled.front().resamples);
    std::vector<double> median, low, high;
    for (const PercentileInterval& p : c.resampled)
      median.push_back(p.median), low.push_back(p.low), high.push_back(p.high);
    putSeries(f, g + "/grid", c.grid, "1");
    putSeries(f, g + "/median", median, "1");
    putSeries(f, g + "/low95", low, "1");
    putSeries(f, g + "/high95", high, "1");
  }
}

}  // namespace

StabilityResults analyseStability(const StabilityConfig& c, const RunSet& runs) {
  StabilityResults r;
  SeedPatterns seeds;
  r.grid = voteGrid(c, runs, seeds);
  r.bootstrap = bootstrapOverSeeds(r.grid, seeds);
  for (const auto& point : seeds.patterns[0])
    r.seeds_per_point.push_back(static_cast<double>(point.size()));
  r.max_seeds = c.max_seeds;
  r.difference_counts = bootstrapDifferenceCounts(r.grid, seeds);
  for (int law = 0; law < kLaws; ++law)
    for (double fr : c.frequencies)
      for (double gamma : c.gammas) {
        r.hydro[law].push_back(hydroPoint(c, runs, law, fr, gamma, false));
        r.hydro_rough[law].push_back(hydroPoint(c, runs, law, fr, gamma, true));
      }
  r.symbol_differences = r.grid.symbolDifferencesPerFrequency();
  r.symbol_differences_within_cycle =
      r.grid.symbolDifferencesPerFrequency(SolidCriterion::within_cycle);
  r.period_differences = r.grid.periodDifferencesPerFrequency();
  r.features = checkPaperFeatures(r.grid);
  r.gallery = gallery(c, runs, r.grid);
  for (int law = 0; law < kLaws; ++law)
    for (double fr : c.frequencies)
      for (double gamma : c.gammas) {
        std::vector<const RunRecord*> records;
        for (int seed : seedsAt(c, runs, fr, gamma))
          records.push_back(&runs.get(StabilityConfig::particleRun(law, fr, gamma, seed)));
        r.spectrum[law].push_back(spectrumWave(records));
      }
  return r;
}

void writeStabilityResults(h5::File& f, const StabilityConfig& c, const StabilityResults& r) {
  f.createGroup(kRoot);
  putSeries(f, kRoot + "/frequencies", c.frequencies, "Hz");
  putSeries(f, kRoot + "/gammas", c.gammas, "1");
  const std::vector<double> seeds(c.seeds.begin(), c.seeds.end());
  putSeries(f, kRoot + "/seeds", seeds, "1");
  putSeries(f, kRoot + "/seeds_per_point", r.seeds_per_point, "1");
  putSeries(f, kRoot + "/differences_per_frequency", r.symbol_differences, "1");
  putSeries(f, kRoot + "/differences_per_frequency_within_cycle", r.symbol_differences_within_cycle,
            "1");
  putSeries(f, kRoot + "/period_differences_per_frequency", r.period_differences, "1");
  for (int law = 0; law < kLaws; ++law) {
    const std::string grp = fmt::format("{}/{}", kRoot, kLawNames[law]);
    writeLaw(f, grp, r.grid.verdicts[law], r.hydro[law], r.hydro_rough[law]);
    std::vector<double> share, amplitude, wavelength;
    for (const SpectrumWave& s : r.spectrum[law]) {
      share.push_back(s.measured() ? s.wave_fraction : NAN);
      amplitude.push_back(s.measured() ? s.amplitude_d : NAN);
      wavelength.push_back(s.measured() ? s.wavelength_d : NAN);
    }
    putSeries(f, grp + "/surface_wave_spectrum_share", share, "1");
    putSeries(f, grp + "/surface_wave_spectrum_amplitude", amplitude, "d");
    putSeries(f, grp + "/surface_wave_spectrum_wavelength", wavelength, "d");
  }
  const std::string features = kRoot + "/features";
  f.createGroup(features);
  for (const FeatureCheck& check : r.features)
    f.writeStringAttribute(features, check.key, check.verdict);
  const std::string boot = kRoot + "/seed_bootstrap";
  f.createGroup(boot);
  f.writeAttribute<std::int64_t>(boot, "resamples", r.bootstrap.resamples);
  int undecided = 0;
  for (const auto& [key, share] : r.bootstrap.verdict_agreement) {
    f.writeAttribute<double>(boot, key, share);
    undecided += share < kDecidedAgreement;
  }
  f.writeAttribute<double>(boot, "undecided", undecided);  // features below the agreement
  writeDifferenceCounts(f, kRoot + "/difference_bootstrap", r.difference_counts);
}

}  // namespace granwave
