#include "studies/momentum_transfer/MomentumTransferReport.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>

#include "scene/SceneDerived.hpp"

namespace granwave {

namespace {

constexpr double kClip = 4.0;  // r_x drawn at most this large in the map

using Results = MomentumTransferResults;

Figure profileFigure(const std::vector<double>& z_over_d, const LayerProfile (&p)[2],
                     std::string title, std::string ylabel, std::string caption) {
  Figure fig;
  fig.title = std::move(title);
  fig.caption = std::move(caption);
  fig.xlabel = "z / d (lab frame)";
  fig.ylabel = std::move(ylabel);
  for (int law = 0; law < kLaws; ++law) {
    Series band;
    band.style = "band";
    band.x = z_over_d;
    band.y_low = p[law].low;
    band.y_high = p[law].high;
    band.color = kLawColors[law];
    fig.series.push_back(std::move(band));
    Series line = lineSeries(z_over_d, p[law].mean, kLawNames[law], kLawColors[law]);
    line.marker = ".";
    fig.series.push_back(std::move(line));
  }
  return fig;
}

Series verticalLine(double x, std::string label, std::string color) {
  Series s = lineSeries({x}, {}, std::move(label), std::move(color));
  s.style = "vline";
  s.linestyle = ":";
  return s;
}

std::string distance(double z) { return std::isfinite(z) ? fmt::format("{:+.1f}", z) : "–"; }

Measurement scaled(const Measurement& m, double factor) {
  return {m.value * factor, m.error * factor};
}

// r_x(z, t) over (t - t_on)/T and z/d, mean over seeds, rows that have a value.
Figure mapFigure(const Results& a, double d, const std::vector<double>& z,
                 const std::string& wet_onsets, double wave_end) {
  Figure fig;
  fig.title = "r_x(z, t) during the wet layer's impact wave";
  fig.xlabel = "(t - t_on) / T";
  fig.ylabel = "z / d (lab frame)";
  fig.legend = false;
  const int n_tau = static_cast<int>(a.tau.size());
  bool clipped = false;
  Image im;
  if (a.j0 >= 0) {
    im.nx = n_tau;
    im.ny = a.j1 - a.j0 + 1;
    for (int j = a.j0; j <= a.j1; ++j)
      for (int i = 0; i < n_tau; ++i) {
        double v = a.map[static_cast<std::size_t>(j) * n_tau + i];
        if (v > kClip) {
          v = kClip;
          clipped = true;
        }
        im.values.push_back(v);
      }
    const double dt = 1.0 / a.per_cycle;
    const double dz = z.size() > 1 ? z[1] - z[0] : d;
    im.x0 = a.tau.front() - 0.5 * dt;
    im.x1 = a.tau.back() + 0.5 * dt;
    im.y0 = (z[a.j0] - 0.5 * dz) / d;
    im.y1 = (z[a.j1] + 0.5 * dz) / d;
    im.label = "r_x = RMS(v_x) dry / RMS(v_x) wet";
    fig.image.push_back(std::move(im));
  }
  fig.series.push_back(verticalLine(0.0, "", "white"));
  fig.series.push_back(verticalLine(wave_end, "", "white"));
  fig.caption = fmt::format(
      "Mean over {} seed(s), each aligned on its wet impact onset (t_on/T = {}); both layers "
      "at the same plate phase. Blank: rows left out (dilute, or no wet RMS). Dotted white "
      "lines: the wave window averaged for r~_x.{}",
      a.ok().size(), wet_onsets,
      clipped ? fmt::format(" Values above {:g} are drawn as {:g}.", kClip, kClip) : "");
  return fig;
}

// <(1 + e_dry(v)) / (1 + e_wet(v))> over the wave's pair impacts of the wet and the dry runs.
template <class Row>
void binaryImpactRows(const BinaryImpactEstimate& b, const Row& row, Table& t) {
  if (!b.missing.empty()) {
    t.rows.push_back({"binary impacts at the wave's speeds", "none: " + b.missing, "–", "–", "–"});
    return;
  }
  for (int law = 1; law >= 0; --law) {
    const PercentileInterval& i = b.bootstrap[law];
    row(fmt::format("binary impacts at the wave's speeds, <(1+e_dry)/(1+e_wet)> over the {} "
                    "runs' {} pair impacts (95 % over seeds {:.3f}–{:.3f}; {:.0f} % below the "
                    "wet onset speed)",
                    kLawNames[law], b.impacts[law], i.low, i.high, 100 * b.below_onset[law]),
        Measurement{b.pooled[law], (i.high - i.low) / (2 * 1.96)}, NAN);
  }
}

Table deficiencyTable(const Results& a) {
  Table t;
  t.title = "Deficiency factor r~_x averaged over the wave window";
  t.caption =
      "Per seed: the mean of r~_x(t) over the window from the profiles pooled over all cycles, "
      "± the spread of the block values / sqrt(blocks). Combined: inverse-variance mean over "
      "seeds (error scaled up by the seeds' scatter). The third column is the spread of "
      "r~_x(t) over the window's phases (what the paper's ± 0.56 appears to be). Δ/σ: "
      "difference over the combined one-sigma errors (the binary value has no error). Binary "
      "impacts: the paper's argument at the speeds the wave's pair impacts have (docs/studies.md), "
      "value from all seeds' impacts, ± half the 95 % bootstrap interval over seeds / 1.96.";
  t.columns = {"source", "r~_x over the wave", "spread of r~_x(t) over the window",
               "Δ/σ to paper 2.17 ± 0.56", "Δ/σ to binary 2"};
  auto row = [&](std::string name, const Measurement& m, double spread) {
    t.rows.push_back({std::move(name), format(m), formatNumber(spread),
                      distance(sigmaDistance(m, kPaperDeficiency)),
                      distance(sigmaDistance(m, kBinaryDeficiency))});
  };
  for (const SeedPair& p : a.pairs) {
    if (!p.failure.empty()) {
      t.rows.push_back({fmt::format("ED seed {}", p.seed), p.failure, "–", "–", "–"});
      continue;
    }
    row(fmt::format("ED seed {} ({} phases)", p.seed, p.pooled.phases_used), p.r, p.pooled.std_dev);
  }
  row(fmt::format("combined, {} seed(s)", a.ok().size()), a.r, a.window_std);
  row("combined, all rows (no area-fraction cut)", a.r_all_rows, NAN);
  row("combined, dry read at the same stage of its own impact", a.r_aligned, NAN);
  for (const SeedPair& p : a.other_pairs)
    if (p.failure.empty())
      row(fmt::format("ED seed {}, {}-cycle window", p.seed, a.other_window), p.r,
          p.pooled.std_dev);
  row(fmt::format("combined, {}-cycle window (the same runs' trajectories; the table above: {} "
                  "cycle(s))",
                  a.other_window, a.window),
      a.r_other_window, NAN);
  row("combined, phase-locked part only (noise subtracted, spread over seeds)", a.r_signal, NAN);
  binaryImpactRows(a.binary_impact, row, t);
  t.rows.push_back({"earlier measurement, docs/fields.md (seed 1, 30 s)",
                    formatNumber(kEarlierDeficiency.value), formatNumber(kEarlierDeficiency.error),
                    distance(sigmaDistance(kEarlierDeficiency, kPaperDeficiency)),
                    distance(sigmaDistance(kEarlierDeficiency, kBinaryDeficiency))});
  t.rows.push_back({"paper (Huang, Sec. V, Fig. 8a)", format(kPaperDeficiency), "–", "0.0",
                    distance(sigmaDistance(kPaperDeficiency, kBinaryDeficiency))});
  t.rows.push_back({"binary collision, e_n = 1 dry vs 0 wet (Sec. V)", "2", "–",
                    distance(sigmaDistance(kBinaryDeficiency, kPaperDeficiency)), "0.0"});
  return t;
}

Table layerTable(const Results& a, int blocks) {
  Table t;
  t.title = "The two layers during the wave window";
  t.caption = fmt::format(
      "RMS(v_x) averaged over the (z, t) cells that enter r~_x and are valid in every block "
      "(± block spread / sqrt(blocks)). Block/pooled: the mean RMS(v_x) of one block of cycles "
      "over the pooled one, 1 for a steady phase-locked flow, sqrt({}) = {:.2f} for pure "
      "statistical noise. Noise share: the part of the mean square RMS(v_x) that is the "
      "statistical noise of the cell means, from <block^2> = S^2 + B N^2 and pooled^2 = S^2 + "
      "N^2. Combined: mean ± standard error over seeds. Onsets to the phase resolution 1/M = "
      "{:g}.",
      blocks, std::sqrt(static_cast<double>(blocks)), 1.0 / a.per_cycle);
  t.columns = {"seed",
               "period dry / wet (T)",
               "impact onset dry / wet (t/T)",
               "RMS(v_x) dry (mm/s)",
               "RMS(v_x) wet (mm/s)",
               "block/pooled RMS dry / wet",
               "noise share of RMS² dry / wet",
               "fraction of cells with r_x > 1"};
  std::vector<double> ratio[2];
  for (const SeedPair& p : a.pairs) {
    if (!p.failure.empty()) {
      t.rows.push_back({std::to_string(p.seed), p.failure, "–", "–", "–", "–", "–", "–"});
      continue;
    }
    auto onset = [&](int law) {
      return p.found[law] ? formatNumber(p.onset[law])
                          : formatNumber(p.onset[law]) + " (no impact front; profile phase)";
    };
    t.rows.push_back(
        {std::to_string(p.seed),
         fmt::format("{} / {}", p.layer[0]->context.layer_period, p.layer[1]->context.layer_period),
         onset(0) + " / " + onset(1), format(scaled(p.rms[0], 1e3), 1),
         format(scaled(p.rms[1], 1e3), 1),
         formatNumber(p.block_ratio[0]) + " / " + formatNumber(p.block_ratio[1]),
         formatNumber(p.noise_share[0]) + " / " + formatNumber(p.noise_share[1]),
         formatNumber(p.above_one)});
    for (int law = 0; law < kLaws; ++law) ratio[law].push_back(p.block_ratio[law]);
  }
  t.rows.push_back(
      {"combined", "–", "–", format(scaled(a.rms[0], 1e3), 1), format(scaled(a.rms[1], 1e3), 1),
       format(meanAndStandardError(ratio[0])) + " / " + format(meanAndStandardError(ratio[1])),
       format(a.noise_share[0]) + " / " + format(a.noise_share[1]), format(a.above_one)});
  return t;
}

std::string perSeed(const Results& a, const std::function<std::string(const SeedPair&)>& item) {
  std::string s;
  for (const SeedPair* p : a.ok()) s += (s.empty() ? "" : ", ") + item(*p);
  return s;
}

std::string layerPeriods(const Results& a) {
  return perSeed(a, [](const SeedPair& p) {
    return fmt::format("seed {}: {} / {}", p.seed, p.layer[0]->context.layer_period,
                       p.layer[1]->context.layer_period);
  });
}

void methodSection(const MomentumTransferConfig& c, const Results& a, Report& report) {
  const std::string periods = layerPeriods(a);
  const std::string onsets = perSeed(a, [](const SeedPair& p) {
    return fmt::format("seed {}: {:.2f} / {:.2f}", p.seed, p.onset[0], p.onset[1]);
  });
  const std::size_t ok = a.ok().size();
  const Scene& dry = c.scenes.base[0];
  report.section(
      "Runs and method",
      fmt::format(
          "The paper's scene (N = {}, f = {:g} Hz, Gamma = {:g}, v0 = {:.3f} m/s) with the dry "
          "and the wet restitution law, {} seed(s) of {:g} s each; fields averaged over windows "
          "of {} cycles (t/T below is the phase within that window) in {} blocks of cycles. "
          "RMS(v_x)(z) is the spread over the columns of the phase-averaged cell velocity v~_x, "
          "i.e. it measures phase-locked horizontal flow, not the thermal motion. Layer period "
          "dry / wet (T): {}. Onset of the strong impact front dry / wet (t/T, to the phase "
          "resolution {:g}): {}. {}",
          dry.particles.count, dry.drive.frequency, derive(dry).gamma, derive(c.scenes.base[1]).v0,
          c.seeds.size(), c.duration, c.window, c.blocks, periods.empty() ? "–" : periods,
          1.0 / a.per_cycle, onsets.empty() ? "–" : onsets,
          ok == a.pairs.size()
              ? std::string("All runs finished.")
              : fmt::format("Only {} of {} seeds have both runs; the others are listed as failed.",
                            ok, a.pairs.size())));
}

void noResultsSection(const Results& a, Report& report) {
  ReportSection& s = report.section("No results", "No seed has both a dry and a wet run.");
  Table t;
  t.title = "Failed runs";
  t.columns = {"seed", "reason"};
  for (const SeedPair& p : a.pairs) t.rows.push_back({std::to_string(p.seed), p.failure});
  s.add(std::move(t));
  Figure ref;
  ref.title = "Reference values only";
  ref.caption = "No run pair to measure r~_x from; the values it would be compared with.";
  ref.xlabel = "(t - t_on) / T";
  ref.ylabel = "r~_x";
  ref.series.push_back(
      horizontalLine(kBinaryDeficiency.value, "binary collision: 2", 0, "tab:red"));
  ref.series.push_back(horizontalLine(kPaperDeficiency.value, "paper: 2.17 ± 0.56",
                                      kPaperDeficiency.error, "tab:green"));
  s.add(std::move(ref));
  report.summary = "- Every seed failed: no deficiency factor was measured.";
}

// Fig. 7: profiles at t/T = 0.88, literally and at the same stage of each layer's impact.
void profilesSection(const MomentumTransferConfig& c, const ImpactProfiles& p, Report& report) {
  const double d = c.scenes.base[0].particles.diameter;
  std::vector<double> z_over_d;
  for (double z : p.z) z_over_d.push_back(z / d);
  std::string literal_text;
  for (double ph : p.literal_phase)
    literal_text += fmt::format("{}{:.2f}", literal_text.empty() ? "" : ", ", ph);
  ReportSection& prof = report.section(
      fmt::format("Profiles at t/T = {:.2f} (Fig. 7)", c.profile_phase),
      fmt::format(
          "Mean vertical velocity v~_z and horizontal velocity fluctuations RMS(v_x), both over "
          "v0, against height, dry and wet. The paper shows them at t/T = {:.2f}, where its "
          "impact begins. Our layers hit the plate at another phase, so the profiles are shown "
          "twice: literally at t/T = {:.2f} (both layers at the same plate phase; window phase "
          "per seed: {}), and at the same stage of each layer's own impact ({:+.2f} T from the "
          "onset of its strong impact front). Lines: mean over seeds of the profiles pooled "
          "over all cycles; bands: one sigma, the spread of the block profiles over seeds x "
          "blocks / sqrt(seeds x blocks). The paper finds comparable v~_z and a larger "
          "RMS(v_x) for the dry layer.",
          kPaperOnset, c.profile_phase, literal_text, c.profile_phase - kPaperOnset));
  const std::string lit = fmt::format("literal t/T = {:.2f}", c.profile_phase);
  const std::string st =
      fmt::format("{:+.2f} T from each layer's impact onset", c.profile_phase - kPaperOnset);
  const char* same_phase = "Both layers at the same plate phase (the paper's definition).";
  const char* same_stage =
      "Each layer at the same stage of its own impact: the paper's t/T = 0.88 moved onto the "
      "onset of the layer's strong impact front.";
  prof.add(profileFigure(z_over_d, p.vz_literal, "v~_z / v0 at " + lit, "v~_z / v0", same_phase));
  prof.add(profileFigure(z_over_d, p.rms_literal, "RMS(v_x) / v0 at " + lit, "RMS(v_x) / v0",
                         same_phase));
  prof.add(profileFigure(z_over_d, p.vz_onset, "v~_z / v0 at " + st, "v~_z / v0", same_stage));
  prof.add(
      profileFigure(z_over_d, p.rms_onset, "RMS(v_x) / v0 at " + st, "RMS(v_x) / v0", same_stage));
}

Figure rowMeanFigure(const Results& a, const std::string& wet_onsets, double wave_end) {
  static const char* kSeedColor[] = {"tab:purple", "tab:brown", "tab:olive", "tab:cyan",
                                     "tab:pink"};
  Figure rm;
  rm.title = "Row mean r~_x against time since the wet impact onset";
  rm.caption = fmt::format(
      "Points: mean over seeds (t_on/T = {}), error bars: spread of the block values over "
      "seeds x blocks / sqrt(seeds x blocks). Thin lines: single seeds. Dashed: the "
      "binary-collision value 2 and the paper's 2.17 ± 0.56 (band); grey: r_x = 1 (no "
      "difference). Dotted: the wave window averaged in the table.",
      wet_onsets);
  rm.xlabel = "(t - t_on) / T";
  rm.ylabel = "r~_x";
  for (const SeedPair* p : a.ok()) {
    Series s = lineSeries(a.tau, p->row_mean_around_wave, fmt::format("seed {}", p->seed),
                          kSeedColor[rm.series.size() % 5]);
    s.linewidth = 0.8;
    rm.series.push_back(std::move(s));
  }
  rm.series.push_back(errorSeries(a.tau, a.row_mean, a.row_error, "mean over seeds", "black"));
  rm.series.push_back(horizontalLine(kBinaryDeficiency.value, "binary collision: 2", 0, "tab:red"));
  rm.series.push_back(horizontalLine(kPaperDeficiency.value, "paper: 2.17 ± 0.56",
                                     kPaperDeficiency.error, "tab:green"));
  Series one = horizontalLine(1.0, "r = 1", 0, "grey");
  one.linestyle = "-";
  rm.series.push_back(std::move(one));
  rm.series.push_back(verticalLine(0.0, "wave window", "black"));
  rm.series.push_back(verticalLine(wave_end, "", "black"));
  return rm;
}

// Fig. 8: the map and the row mean, and the tables.
void deficiencySection(const MomentumTransferConfig& c, const Results& a, Report& report) {
  const std::string wet_onsets =
      perSeed(a, [](const SeedPair& p) { return fmt::format("{:.2f}", p.onset[1]); });
  const double wave_end = static_cast<double>(a.n_wave) / a.per_cycle;
  ReportSection& def = report.section(
      "Deficiency factor r_x = RMS(v_x)_dry / RMS(v_x)_wet (Fig. 8)",
      fmt::format(
          "r_x(z, t) compares the two layers at the same plate phase, as in the paper. Time is "
          "counted from the onset t_on of the wet layer's strong impact front (per seed); the "
          "wave window averaged for r~_x is the first {:g} T ({} phases) from it. r~_x(t) = "
          "<r_x(z_j, t)>_j over the rows where both layers have an area fraction of at least "
          "{:g} (inside the layers; the dilute gas above has few particles and a noisy ratio) "
          "and the wet RMS(v_x) is at least {:g} m/s. Errors: the spread of the same quantity "
          "computed from each block of cycles / sqrt(blocks); across seeds the inverse-variance "
          "mean, its error scaled up when the seeds scatter more than their errors.",
          wave_end, a.n_wave, c.min_area_fraction, c.min_rms));
  def.add(mapFigure(a, c.scenes.base[0].particles.diameter, a.profiles.z, wet_onsets, wave_end));
  def.add(rowMeanFigure(a, wet_onsets, wave_end));
  def.add(deficiencyTable(a));
  def.add(layerTable(a, c.blocks));
}

// What the runs give: the verdict, its direction, why, how much is flow, and sensitivity.
void verdictSection(const MomentumTransferConfig& c, const Results& a, Report& report) {
  const double wave_end = static_cast<double>(a.n_wave) / a.per_cycle;
  const char* decided = !std::isfinite(a.z_paper)    ? "not reproduced, no value to compare"
                        : std::abs(a.z_paper) <= 2.0 ? "reproduced, within 2 sigma"
                                                     : "not reproduced, more than 2 sigma away";
  const std::string verdict = fmt::format(
      "- The runs give r~_x = {} over the first {:g} T of the wet layer's impact wave "
      "(combined over {} seed(s) of {:g} s; spread of r~_x(t) over the window {}).\n"
      "- Against the paper's 2.17 ± 0.56: {} ({} sigma).\n"
      "- Against the binary-collision value 2: {} sigma.\n",
      format(a.r), wave_end, a.ok().size(), c.duration, formatNumber(a.window_std), decided,
      distance(a.z_paper), distance(a.z_binary));
  const std::string rms_pair = fmt::format("{} against {} mm/s", format(scaled(a.rms[0], 1e3), 1),
                                           format(scaled(a.rms[1], 1e3), 1));
  std::string direction;
  if (a.r.valid())
    direction =
        a.r.value < 1.0
            ? fmt::format(
                  "- r~_x is below 1: RMS(v_x) of the dry layer is smaller than the wet layer's "
                  "({} over the cells averaged), the reverse of the paper's deficiency; r_x > 1 "
                  "in a fraction {} of the (z, t) cells of the window, where the paper has r_x "
                  "predominantly > 1.\n",
                  rms_pair, format(a.above_one))
            : fmt::format(
                  "- r~_x is above 1: RMS(v_x) of the wet layer is smaller than the dry layer's "
                  "({}), as in the paper; r_x > 1 in a fraction {} of the (z, t) cells of the "
                  "window.\n",
                  rms_pair, format(a.above_one));
  std::string ratios;
  for (const SeedPair* p : a.ok())
    ratios += fmt::format("{}seed {}: {} / {}", ratios.empty() ? "" : ", ", p->seed,
                          formatNumber(p->block_ratio[0]), formatNumber(p->block_ratio[1]));
  const double sqrt_b = std::sqrt(static_cast<double>(c.blocks));
  const std::string why = fmt::format(
      "The earlier measurement with this code (docs/fields.md, seed 1, 30 s) gave r~_x = 0.60 "
      "± 0.22 (spread over 35 front phases), and docs/fields.md gives the reason: in this model "
      "the dry layer, whose restitution is about 0.9 at its impact speeds, stays period 1 "
      "without surface waves (a hot, dilute gas in flight), while the wet layer, whose "
      "contacts do not rebound below v_c and are effectively far more dissipative, forms a "
      "phase-locked roll and a standing f/2 wave and switches between period 1 and 2. That is "
      "the reverse of the paper (surface waves dry, none wet), so the ratio that the paper "
      "reads as a deficiency of momentum transfer due to wetting comes out below 1 here. Layer "
      "periods dry / wet in these runs: {}.",
      layerPeriods(a));
  const bool noisy[2] = {a.noise_share[0].value > 0.5, a.noise_share[1].value > 0.5};
  const std::string noise_note = noisy[0] && noisy[1]
                                     ? ": r_x compares mostly the noise floors of the two layers"
                                 : noisy[0] ? ": the dry layer's RMS(v_x) is mostly noise"
                                 : noisy[1] ? ": the wet layer's RMS(v_x) is mostly noise"
                                            : "";
  const std::string noise = fmt::format(
      "How much of RMS(v_x) is flow: the ratio of a single block's RMS(v_x) to the one "
      "pooled over all cycles is 1 for a steady phase-locked flow and sqrt(blocks) = {:.2f} "
      "for pure statistical noise of the cell means; here it is {} (dry / wet). Splitting the "
      "mean square RMS(v_x) of the window's cells accordingly, the noise share is {} (dry) and "
      "{} (wet){}, and the ratio of the phase-locked parts alone is {} (mean ± standard error "
      "over seeds; this assumes the flow is the same in every block, and a wet layer that "
      "switches period between blocks makes part of its flow count as noise).",
      sqrt_b, ratios, format(a.noise_share[0]), format(a.noise_share[1]), noise_note,
      format(a.r_signal));
  const std::string sensitivity = fmt::format(
      "Sensitivity: without the area-fraction cut r~_x = {}; with the dry layer read at the "
      "same stage of its own impact instead of the same plate phase r~_x = {}. The "
      "binary-collision value 2 (e_n = 1 dry against 0 wet, Sec. V) is a statement about "
      "single collisions; the ratio of phase-averaged flows that r_x measures also depends on "
      "the collective state of each layer, which differs here as described above.",
      format(a.r_all_rows), format(a.r_aligned));
  // The explanation of docs/fields.md applies only when these runs show what it explains.
  const bool below_one = a.r.valid() && a.r.value < 1;
  report.section("What the runs give", verdict + direction + "\n" +
                                           (below_one ? why + "\n\n" : std::string()) + noise +
                                           "\n\n" + sensitivity);
  report.summary = verdict + direction;
}

}  // namespace

void reportMomentumTransfer(const MomentumTransferConfig& c, const MomentumTransferResults& a,
                            Report& report) {
  methodSection(c, a, report);
  if (a.ok().empty()) {
    noResultsSection(a, report);
    return;
  }
  profilesSection(c, a.profiles, report);
  deficiencySection(c, a, report);
  verdictSection(c, a, report);
}

}  // namespace granwave
