#include "studies/momentum_transfer/MomentumTransferAnalysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/SceneDerived.hpp"
#include "studies/contract/FailureReason.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/wave_analysis/ImpactFronts.hpp"

namespace granwave {

namespace {

const std::string kRoot = "/results/momentum_transfer";

int wrap(int k, int n) { return ((k % n) + n) % n; }

double circularDistance(double a, double b, double period) {
  const double d = std::fmod(std::abs(a - b), period);
  return std::min(d, period - d);
}

double stdDev(const std::vector<double>& v) {
  double s = 0, s2 = 0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) {
      s += x;
      s2 += x * x;
      ++n;
    }
  if (n < 2) return NAN;
  const double mean = s / n;
  return std::sqrt(std::max(0.0, (s2 - n * mean * mean) / (n - 1)));
}

// A profile value: block < 0 the profile pooled over all cycles, else that block's.
double value(const FieldsRecord& p, bool rms, int block, int k, int j) {
  const PhaseFields& f = block < 0 ? p.profiles.pooled : p.profiles.blocks[block];
  return (rms ? f.profile_rms_velocity_x : f.profile_velocity_z)[f.row(k, j)];
}

// r_x(z, t) of one seed from the pooled profiles (block < 0) or one block's. The dry layer is
// read `shift` phases after the wet one (0: the same plate phase, the paper's definition); rows
// where either layer's pooled area fraction is below min_af are left out.
Deficiency ratioOf(const FieldsRecord& dry, const FieldsRecord& wet, int block, int shift,
                   double min_af, double min_rms, const std::vector<bool>& select) {
  const PhaseProfiles &d = dry.profiles, &w = wet.profiles;
  return momentumDeficiency(d.pooled, w.pooled, {select, min_rms, min_af, shift},
                            block < 0 ? nullptr : &d.blocks[block],
                            block < 0 ? nullptr : &w.blocks[block]);
}

// Both runs of the seed and the onsets of their strong impact fronts; false if unusable.
bool readLayers(const MomentumTransferConfig& c, const RunSet& runs, SeedPair& p) {
  for (int law = 0; law < kLaws; ++law) {
    const RunRecord& r = runs.get(
        p.other_window > 0 ? MomentumTransferConfig::otherWindowLabel(law, p.seed, p.other_window)
                           : MomentumTransferConfig::label(law, p.seed));
    if (!r.ok) {
      p.failure += fmt::format("{}{} run failed: {}", p.failure.empty() ? "" : "; ", kLawNames[law],
                               shortReason(r.message));
      continue;
    }
    p.layer[law] = readFieldsFile(r.fieldsPath());
  }
  if (!p.failure.empty()) return false;
  const FieldsRecord& dry = *p.layer[0];
  const FieldsRecord& wet = *p.layer[1];
  if (dry.profiles.phases() != wet.profiles.phases() ||
      dry.profiles.rows() != wet.profiles.rows() ||
      dry.cycles_per_window != wet.cycles_per_window) {
    p.failure = "failed: the dry and wet fields have different phases or rows";
    return false;
  }
  p.blocks = std::min(dry.blocks, wet.blocks);
  p.per_cycle = wet.cycles_per_window > 0 ? wet.profiles.phases() / wet.cycles_per_window
                                          : wet.profiles.phases();
  for (int law = 0; law < kLaws; ++law) {
    const FieldsRecord& l = *p.layer[law];
    const ImpactFronts imp = impactFronts(l.profiles);
    p.found[law] = imp.strong_start >= 0;
    p.onset[law] = p.found[law] ? imp.strong_start : c.profile_phase;
    p.on[law] = l.profiles.phaseIndex(p.onset[law]);
  }
  return true;
}

// The wave window: from the wet layer's onset for wave_duration.
std::vector<bool> waveWindow(const MomentumTransferConfig& c, const SeedPair& p) {
  const int phases = p.layer[1]->profiles.phases();
  const int n_wave = std::max(1, static_cast<int>(std::lround(c.wave_duration * p.per_cycle)));
  std::vector<bool> select(phases, false);
  for (int i = 0; i < n_wave; ++i) select[wrap(p.on[1] + i, phases)] = true;
  return select;
}

// r_x over the wave window, pooled and (for the error) per block.
void waveRatios(const MomentumTransferConfig& c, const std::vector<bool>& select, SeedPair& p) {
  const FieldsRecord& dry = *p.layer[0];
  const FieldsRecord& wet = *p.layer[1];
  auto wave = [&](int shift, double min_af, bool keep) {
    const Deficiency all = ratioOf(dry, wet, -1, shift, min_af, c.min_rms, select);
    std::vector<double> per_block;
    for (int b = 0; b < p.blocks; ++b) {
      Deficiency one = ratioOf(dry, wet, b, shift, min_af, c.min_rms, select);
      per_block.push_back(one.mean);
      if (keep) p.blocks_r.push_back(std::move(one));
    }
    if (keep) p.pooled = all;
    return Measurement{all.mean, stdDev(per_block) / std::sqrt(p.blocks)};
  };
  p.r = wave(0, c.min_area_fraction, true);
  p.r_all_rows = wave(0, 0.0, false);
  p.r_aligned = wave(p.on[0] - p.on[1], c.min_area_fraction, false);
}

// The (z, t) cells entering r~_x that are valid in every block of both layers; also the
// fraction of the cells entering r~_x with r_x > 1.
std::vector<std::pair<int, int>> cellsInEveryBlock(const std::vector<bool>& select, SeedPair& p) {
  const FieldsRecord& wet = *p.layer[1];
  int above = 0, cells = 0;
  std::vector<std::pair<int, int>> used;
  for (int k = 0; k < wet.profiles.phases(); ++k) {
    if (!select[k]) continue;
    for (int j = 0; j < wet.profiles.rows(); ++j) {
      const double ratio = p.pooled.ratio[static_cast<std::size_t>(k) * wet.profiles.rows() + j];
      if (!std::isfinite(ratio)) continue;
      ++cells;
      above += ratio > 1.0;
      bool all = true;
      for (int law = 0; law < kLaws; ++law)
        for (int b = 0; b < p.blocks; ++b)
          all = all && std::isfinite(value(*p.layer[law], true, b, k, j));
      if (all) used.emplace_back(k, j);
    }
  }
  p.above_one = cells ? static_cast<double>(above) / cells : NAN;
  return used;
}

// RMS(v_x) of one layer over the cells, pooled and per block, and its split into flow and noise.
void rmsDecomposition(const std::vector<std::pair<int, int>>& used, int law, SeedPair& p) {
  const FieldsRecord& l = *p.layer[law];
  std::vector<double> pooled, blocks(p.blocks, 0.0);
  double p2 = 0, b2 = 0;
  for (const auto& [k, j] : used) {
    const double v = value(l, true, -1, k, j);
    pooled.push_back(v);
    p2 += v * v;
    for (int b = 0; b < p.blocks; ++b) {
      const double vb = value(l, true, b, k, j);
      blocks[b] += vb;
      b2 += vb * vb / p.blocks;
    }
  }
  const double n = static_cast<double>(used.size()), B = p.blocks;
  for (double& b : blocks) b /= n;
  const double mean = meanAndStandardError(pooled).value;
  p.rms[law] = {mean, stdDev(blocks) / std::sqrt(B)};
  p.block_ratio[law] = meanAndStandardError(blocks).value / mean;
  p.signal2[law] = (B * p2 - b2) / (B - 1) / n;
  p.noise_share[law] = (b2 - p2) / (B - 1) / p2;
}

void analysePair(const MomentumTransferConfig& c, const RunSet& runs, SeedPair& p) {
  if (!readLayers(c, runs, p)) return;
  const std::vector<bool> select = waveWindow(c, p);
  p.wave = select;
  waveRatios(c, select, p);
  const std::vector<std::pair<int, int>> used = cellsInEveryBlock(select, p);
  for (int law = 0; law < kLaws && !used.empty(); ++law) rmsDecomposition(used, law, p);
  if (p.signal2[0] > 0 && p.signal2[1] > 0) p.r_signal = std::sqrt(p.signal2[0] / p.signal2[1]);
}

// Combined over the usable seeds.
void combineSeeds(MomentumTransferResults& a) {
  std::vector<Measurement> r, all_rows, aligned, rms[2];
  std::vector<double> above, r_signal, noise[2];
  for (const SeedPair* p : a.ok()) {
    r_signal.push_back(p->r_signal);
    for (int law = 0; law < kLaws; ++law) noise[law].push_back(p->noise_share[law]);
    r.push_back(p->r);
    all_rows.push_back(p->r_all_rows);
    aligned.push_back(p->r_aligned);
    above.push_back(p->above_one);
    for (int law = 0; law < kLaws; ++law) rms[law].push_back(p->rms[law]);
  }
  a.r = combine(r);
  a.r_all_rows = combine(all_rows);
  a.r_aligned = combine(aligned);
  for (int law = 0; law < kLaws; ++law) a.rms[law] = combine(rms[law]);
  a.above_one = meanAndStandardError(above);
  a.r_signal = meanAndStandardError(r_signal);
  for (int law = 0; law < kLaws; ++law) a.noise_share[law] = meanAndStandardError(noise[law]);
  a.z_paper = sigmaDistance(a.r, kPaperDeficiency);
  a.z_binary = sigmaDistance(a.r, kBinaryDeficiency);
}

// r~_x(t) and r_x(z, t) around the wave, each seed aligned on its wet onset.
void waveMaps(MomentumTransferResults& a) {
  const std::vector<const SeedPair*> ok = a.ok();
  const int n_tau = a.n_wave + 2 * a.n_margin;
  a.map.assign(static_cast<std::size_t>(a.nz) * n_tau, kNaN);
  for (int i = 0; i < n_tau; ++i) {
    const int offset = i - a.n_margin;
    a.tau.push_back(static_cast<double>(offset) / a.per_cycle);
    std::vector<double> pooled, blocks;
    for (const SeedPair* p : ok) {
      const int k = wrap(p->on[1] + offset, p->layer[1]->profiles.phases());
      pooled.push_back(p->pooled.row_mean[k]);
      for (const Deficiency& b : p->blocks_r) blocks.push_back(b.row_mean[k]);
    }
    a.row_mean.push_back(meanAndStandardError(pooled).value);
    a.row_error.push_back(meanAndStandardError(blocks).error);
    for (int j = 0; j < a.nz; ++j) {
      std::vector<double> v;
      for (const SeedPair* p : ok) {
        const int k = wrap(p->on[1] + offset, p->layer[1]->profiles.phases());
        v.push_back(p->pooled.ratio[static_cast<std::size_t>(k) * a.nz + j]);
      }
      const double m = meanAndStandardError(v).value;
      a.map[static_cast<std::size_t>(j) * n_tau + i] = m;
      if (std::isfinite(m)) {
        if (a.j0 < 0 || j < a.j0) a.j0 = j;
        a.j1 = std::max(a.j1, j);
      }
    }
  }
  std::vector<double> window;
  for (int i = a.n_margin; i < a.n_margin + a.n_wave; ++i) window.push_back(a.row_mean[i]);
  a.window_std = stdDev(window);
  for (SeedPair& p : a.pairs) {
    if (!p.failure.empty()) continue;
    for (int i = 0; i < n_tau; ++i)
      p.row_mean_around_wave.push_back(
          p.pooled.row_mean[wrap(p.on[1] + i - a.n_margin, p.layer[1]->profiles.phases())]);
  }
}

// Mean over seeds of a profile at one phase index per seed (and layer), scaled; the error is
// the spread of the block profiles over seeds x blocks / sqrt(seeds x blocks).
LayerProfile layerProfile(const std::vector<const SeedPair*>& ok, const std::vector<int>& k,
                          int law, bool rms, double scale) {
  LayerProfile out;
  const int nz = ok.front()->layer[law]->profiles.rows();
  for (int j = 0; j < nz; ++j) {
    std::vector<double> pooled, blocks;
    for (std::size_t s = 0; s < ok.size(); ++s) {
      const FieldsRecord& p = *ok[s]->layer[law];
      pooled.push_back(value(p, rms, -1, k[s], j));
      for (int b = 0; b < ok[s]->blocks; ++b) blocks.push_back(value(p, rms, b, k[s], j));
    }
    const double m = meanAndStandardError(pooled).value * scale;
    const double e = meanAndStandardError(blocks).error * scale;
    out.mean.push_back(m);
    out.low.push_back(m - e);
    out.high.push_back(m + e);
  }
  return out;
}

// Fig. 7: each seed's wet window phase nearest the paper's t/T (within the cycle of its
// onset), and the same stage of each layer's own impact.
ImpactProfiles impactProfiles(const MomentumTransferConfig& c, const MomentumTransferResults& a) {
  const std::vector<const SeedPair*> ok = a.ok();
  const double v0 = derive(c.scenes.base[1]).v0;
  ImpactProfiles out;
  out.z = ok.front()->layer[1]->profiles.z;
  std::vector<int> literal, stage[2];
  const int stage_shift =
      static_cast<int>(std::lround((c.profile_phase - kPaperOnset) * a.per_cycle));
  for (const SeedPair* p : ok) {
    const FieldsRecord& wet = *p->layer[1];
    double best = c.profile_phase;
    for (int cyc = 1; cyc < wet.cycles_per_window; ++cyc)
      if (circularDistance(c.profile_phase + cyc, p->onset[1], wet.cycles_per_window) <
          circularDistance(best, p->onset[1], wet.cycles_per_window))
        best = c.profile_phase + cyc;
    literal.push_back(wet.profiles.phaseIndex(best));
    out.literal_phase.push_back(wet.profiles.phase[literal.back()]);
    for (int law = 0; law < kLaws; ++law)
      stage[law].push_back(wrap(p->on[law] + stage_shift, p->layer[law]->profiles.phases()));
  }
  for (int law = 0; law < kLaws; ++law) {
    out.vz_literal[law] = layerProfile(ok, literal, law, false, 1 / v0);
    out.rms_literal[law] = layerProfile(ok, literal, law, true, 1 / v0);
    out.vz_onset[law] = layerProfile(ok, stage[law], law, false, 1 / v0);
    out.rms_onset[law] = layerProfile(ok, stage[law], law, true, 1 / v0);
  }
  return out;
}

void writeSeeds(h5::File& f, const MomentumTransferResults& a) {
  for (const SeedPair& p : a.pairs) {
    const std::string g = fmt::format("{}/seed_{}", kRoot, p.seed);
    putValue(f, g, "ok", p.failure.empty() ? 1 : 0);
    if (!p.failure.empty()) continue;
    putMeasurement(f, g, "r_x_wave", p.r);
    putMeasurement(f, g, "r_x_wave_all_rows", p.r_all_rows);
    putMeasurement(f, g, "r_x_wave_dry_at_own_onset", p.r_aligned);
    putValue(f, g, "r_x_wave_std_over_phases", p.pooled.std_dev);
    putValue(f, g, "phases_used", p.pooled.phases_used);
    putValue(f, g, "fraction_r_x_above_1", p.above_one);
    putValue(f, g, "r_x_wave_phase_locked_part", p.r_signal);
    for (int law = 0; law < kLaws; ++law) {
      const std::string n = kLawNames[law];
      putValue(f, g, "impact_onset_" + n, p.onset[law]);
      putValue(f, g, "impact_front_found_" + n, p.found[law] ? 1 : 0);
      putValue(f, g, "layer_period_" + n, p.layer[law]->context.layer_period);
      putMeasurement(f, g, "rms_velocity_x_" + n, p.rms[law]);
      putValue(f, g, "block_to_pooled_rms_" + n, p.block_ratio[law]);
      putValue(f, g, "noise_share_rms2_" + n, p.noise_share[law]);
    }
  }
}

void writeWave(h5::File& f, const MomentumTransferResults& a) {
  const std::string g = kRoot + "/wave";
  f.createGroup(g);
  putSeries(f, g + "/time_since_wet_onset", a.tau, "T");
  putSeries(f, g + "/row_mean_r_x", a.row_mean, "1");
  putSeries(f, g + "/row_mean_r_x_error", a.row_error, "1");
  putSeries(f, g + "/z", a.ok().front()->layer[1]->profiles.z, "m");
  f.writeDataset(g + "/r_x", a.map,
                 {static_cast<std::size_t>(a.nz), static_cast<std::size_t>(a.tau.size())});
  f.writeStringAttribute(g + "/r_x", "unit", "1");
}

std::vector<double> halfWidth(const LayerProfile& p) {
  std::vector<double> e;
  for (std::size_t j = 0; j < p.mean.size(); ++j) e.push_back(0.5 * (p.high[j] - p.low[j]));
  return e;
}

void writeProfiles(h5::File& f, const ImpactProfiles& p) {
  const std::string g = kRoot + "/profiles";
  f.createGroup(g);
  putSeries(f, g + "/z", p.z, "m");
  for (int law = 0; law < kLaws; ++law) {
    const std::string n = kLawNames[law];
    putSeries(f, g + "/literal_velocity_z_" + n, p.vz_literal[law].mean, "v0");
    putSeries(f, g + "/literal_rms_velocity_x_" + n, p.rms_literal[law].mean, "v0");
    putSeries(f, g + "/onset_velocity_z_" + n, p.vz_onset[law].mean, "v0");
    putSeries(f, g + "/onset_rms_velocity_x_" + n, p.rms_onset[law].mean, "v0");
    putSeries(f, g + "/literal_velocity_z_error_" + n, halfWidth(p.vz_literal[law]), "v0");
    putSeries(f, g + "/literal_rms_velocity_x_error_" + n, halfWidth(p.rms_literal[law]), "v0");
    putSeries(f, g + "/onset_velocity_z_error_" + n, halfWidth(p.vz_onset[law]), "v0");
    putSeries(f, g + "/onset_rms_velocity_x_error_" + n, halfWidth(p.rms_onset[law]), "v0");
  }
}

}  // namespace

std::vector<const SeedPair*> MomentumTransferResults::ok() const {
  std::vector<const SeedPair*> v;
  for (const SeedPair& p : pairs)
    if (p.failure.empty()) v.push_back(&p);
  return v;
}

MomentumTransferResults analyseMomentumTransfer(const MomentumTransferConfig& c,
                                                const RunSet& runs) {
  MomentumTransferResults a;
  for (int seed : c.seeds) {
    SeedPair p;
    p.seed = seed;
    analysePair(c, runs, p);
    a.pairs.push_back(std::move(p));
  }
  a.window = c.window;
  a.other_window = c.otherWindow();
  std::vector<Measurement> other;
  for (int seed : c.seeds) {
    SeedPair p;
    p.seed = seed;
    p.other_window = a.other_window;
    analysePair(c, runs, p);
    if (p.failure.empty()) other.push_back(p.r);
    a.other_pairs.push_back(std::move(p));
  }
  a.r_other_window = combine(other);
  const std::vector<const SeedPair*> ok = a.ok();
  if (ok.empty()) return a;
  a.per_cycle = ok.front()->per_cycle;
  a.nz = ok.front()->layer[1]->profiles.rows();
  a.n_wave = std::max(1, static_cast<int>(std::lround(c.wave_duration * a.per_cycle)));
  a.n_margin = static_cast<int>(std::lround(c.margin * a.per_cycle));
  combineSeeds(a);
  std::vector<int> seeds;
  std::vector<std::vector<bool>> waves;
  for (const SeedPair* p : ok) seeds.push_back(p->seed), waves.push_back(p->wave);
  a.binary_impact = binaryImpactEstimate(c, runs, seeds, waves);
  waveMaps(a);
  a.profiles = impactProfiles(c, a);
  return a;
}

void writeMomentumTransferResults(h5::File& f, const MomentumTransferConfig& c,
                                  const MomentumTransferResults& a) {
  f.createGroup(kRoot);
  putMeasurement(f, kRoot, "r_x_wave", a.r);
  putMeasurement(f, kRoot, "r_x_wave_all_rows", a.r_all_rows);
  putMeasurement(f, kRoot, "r_x_wave_dry_at_own_onset", a.r_aligned);
  putMeasurement(f, kRoot, fmt::format("r_x_wave_window_{}", a.window), a.r);
  putMeasurement(f, kRoot, fmt::format("r_x_wave_window_{}", a.other_window), a.r_other_window);
  putValue(f, kRoot, "r_x_wave_std_over_phases", a.window_std);
  putMeasurement(f, kRoot, "fraction_r_x_above_1", a.above_one);
  putMeasurement(f, kRoot, "rms_velocity_x_dry", a.rms[0]);
  putMeasurement(f, kRoot, "rms_velocity_x_wet", a.rms[1]);
  putMeasurement(f, kRoot, "r_x_wave_phase_locked_part", a.r_signal);
  putMeasurement(f, kRoot, "noise_share_rms2_dry", a.noise_share[0]);
  putMeasurement(f, kRoot, "noise_share_rms2_wet", a.noise_share[1]);
  putMeasurement(f, kRoot, "paper_r_x", kPaperDeficiency);
  putValue(f, kRoot, "binary_collision_r_x", kBinaryDeficiency.value);
  putValue(f, kRoot, "sigma_to_paper", a.z_paper);
  putValue(f, kRoot, "sigma_to_binary", a.z_binary);
  putValue(f, kRoot, "seeds_used", static_cast<double>(a.ok().size()));
  putValue(f, kRoot, "wave_duration", c.wave_duration);
  putValue(f, kRoot, "profile_phase", c.profile_phase);
  putValue(f, kRoot, "min_area_fraction", c.min_area_fraction);
  putValue(f, kRoot, "min_rms", c.min_rms);
  writeSeeds(f, a);
  writeBinaryImpactEstimate(f, kRoot, a.binary_impact);
  if (a.tau.empty()) return;
  writeWave(f, a);
  writeProfiles(f, a.profiles);
}

}  // namespace granwave
