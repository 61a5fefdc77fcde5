#include "studies/surface_waves/SurfaceWavesReport.hpp"

#include <fmt/format.h>

#include <cmath>

namespace granwave {

namespace {

const char* kColors[] = {"tab:orange", "tab:blue", "tab:green", "tab:red",   "tab:purple",
                         "tab:brown",  "tab:pink", "tab:gray",  "tab:olive", "tab:cyan"};

// Points joined or not, with a marker (std::string arguments: assigning short literals to the
// Series' strings trips GCC 12's false -Wrestrict, PR 105329).
Series marked(Series s, std::string marker, std::string linestyle) {
  s.marker = std::move(marker);
  s.linestyle = std::move(linestyle);
  return s;
}

std::string onsetText(const SurfaceWaveOnset& o) {
  return o.gamma_c.valid() ? format(o.gamma_c) : fmt::format("Gamma_c {}", o.bound);
}

std::string method(const SurfaceWavesConfig& c) {
  std::string variants;
  for (const SurfaceWaveVariant& v : c.variants) {
    std::string set;
    for (const std::string& s : v.set) set += fmt::format("{}{}", set.empty() ? "" : ", ", s);
    variants += fmt::format("{}{} ({} law{})", variants.empty() ? "" : "; ", v.name,
                            kLawNames[v.law], set.empty() ? "" : fmt::format(", {}", set));
  }
  return fmt::format(
      "Variants: {}. Every run lasts {} cycles; seeds {}. The surface h(x, t) is the height "
      "above the plate where a column's coarse-grained area fraction falls through half the "
      "layer's bulk value (Gaussian kernel of d/2), at every recorded phase "
      "(coarse_grain/LayerSurface.hpp). Its spectrum is taken over windows of 10 steady "
      "cycles: per surface mode the part that alternates every cycle (f/2 family), the part "
      "that repeats every cycle (f family) and the rest (coarse_grain/SurfaceWaveSpectrum.hpp). "
      "A window has a wave when its strongest f/2 mode has an amplitude (that of the f/2 "
      "sinusoid of the same power, noise power removed) of at least 0.5 d and three noise "
      "floors, and at least half of its locked power at f/2. Errors: "
      "standard errors over windows, combined over seeds with the seeds' scatter. The "
      "stability study's detector (one phase of 16 cycles, yes/no) is shown beside it.",
      variants, c.cycles, [&] {
        std::string s;
        for (int x : c.seeds) s += fmt::format("{}{}", s.empty() ? "" : ", ", x);
        return s;
      }());
}

void addOnset(const SurfaceWavesConfig& c, const SurfaceWavesResults& r, Report& report) {
  ReportSection& sec = report.section(
      "Onset of f/2 surface waves",
      fmt::format("Base box: W = {} d, {}, {} rows. A point waves when half its windows or more "
                  "(seeds pooled, counted) have a wave; Gamma_c is where the share of windows with "
                  "a wave rises through 1/2 (SurfaceWaveOnset.hpp).",
                  formatCompact(c.width_d), c.periodic ? "periodic" : "side walls", c.rows));
  for (double f : c.frequencies) {
    Figure fig;
    fig.title = fmt::format("Share of windows with an f/2 wave, f = {} Hz", formatCompact(f));
    fig.xlabel = "Gamma";
    fig.ylabel = "share of windows";
    for (std::size_t v = 0; v < c.variants.size(); ++v) {
      std::vector<double> x, y;
      for (const SurfaceWaveSummary& s : r.onset)
        if (s.point.variant == static_cast<int>(v) && s.point.frequency == f && s.ok > 0)
          x.push_back(s.point.gamma), y.push_back(s.wave_fraction);
      fig.series.push_back(marked(lineSeries(x, y, c.variants[v].name, kColors[v % 10]), "o", ""));
    }
    fig.series.push_back(horizontalLine(0.5, "onset level"));
    sec.add(fig);
  }
  Table t;
  t.title = "Onset Gamma_c per variant and frequency";
  t.columns = {"variant"};
  for (double f : c.frequencies) t.columns.push_back(fmt::format("f = {} Hz", formatCompact(f)));
  for (std::size_t v = 0; v < c.variants.size(); ++v) {
    std::vector<std::string> row{c.variants[v].name};
    for (const SurfaceWaveOnset& o : r.onsets)
      if (o.variant == static_cast<int>(v)) row.push_back(onsetText(o));
    t.rows.push_back(row);
  }
  sec.add(t);
}

void addDissipation(const SurfaceWavesConfig& c, const SurfaceWavesResults& r, Report& report) {
  ReportSection& sec = report.section(
      "Does the onset follow the layer's dissipation?",
      fmt::format(
          "Each variant's dissipation at f = {} Hz, Gamma = {}: the effective restitution of its "
          "pair impacts, e_eff = sqrt(1 - loss / normal impact energy) over the impacts the "
          "restitution law decided (TC-elastic ones excluded), and the energy it loses per cycle "
          "over its mean kinetic energy (all collisions). Spearman's rank correlation of Gamma_c "
          "with e_eff over the {} variants with an onset: {} (undefined when the onsets tie, "
          "i.e. fall between the same two Gamma of the grid).",
          formatCompact(c.frequencies.front()), formatCompact(c.dissipation_gamma),
          r.ranked_variants, formatNumber(r.rank_correlation, 2)));
  Figure fig;
  fig.title = "Onset against the layer's effective restitution";
  fig.xlabel = "e_eff of the pair impacts";
  fig.ylabel = "Gamma_c";
  Table t;
  t.title = "Dissipation and onset per variant";
  t.columns = {"variant", "e_eff", "energy lost per cycle / kinetic energy", "Gamma_c"};
  for (const VariantDissipation& d : r.dissipation) {
    t.rows.push_back({c.variants[d.variant].name, format(d.e_eff, 3), format(d.loss_per_cycle),
                      d.gamma_c.valid() ? format(d.gamma_c) : d.gamma_c_bound});
    if (!d.gamma_c.valid() || !d.e_eff.valid()) continue;
    Series p = errorSeries({d.e_eff.value}, {d.gamma_c.value}, {d.gamma_c.error},
                           c.variants[d.variant].name, kColors[d.variant % 10]);
    p.xerr = {d.e_eff.error};
    fig.series.push_back(marked(std::move(p), "o", "none"));
  }
  sec.add(fig);
  sec.add(t);
}

void addMomentumRatio(const SurfaceWavesResults& r, Report& report) {
  ReportSection& sec = report.section(
      "r_x beside the spectrum",
      fmt::format("The paper's deficiency factor r_x = RMS(v_x)_dry / RMS(v_x)_wet "
                  "(studies/wave_analysis/WaveMomentumRatio: the rows' mean over 0.15 T from the "
                  "wet strong impact), for the variants named dry and wet in the base box, mean "
                  "and standard error over seeds. Points where neither layer has a wave are the "
                  "noise floor. With waves in either layer: {}; without waves in either: {}.",
                  format(r.r_x_waves), format(r.r_x_control)));
  Table t;
  t.title = "r_x and the waves of the two layers";
  t.columns = {
      "f (Hz)",       "Gamma", "r_x", "dry: windows with a wave", "wet: windows with a wave",
      "noise control"};
  for (const MomentumRatioPoint& p : r.r_x)
    t.rows.push_back(
        {formatCompact(p.frequency), formatCompact(p.gamma), format(p.r_x),
         fmt::format("{:.0f} %{}", 100 * p.dry_wave_fraction, p.dry_waves ? " (waves)" : ""),
         fmt::format("{:.0f} %{}", 100 * p.wet_wave_fraction, p.wet_waves ? " (waves)" : ""),
         p.control() ? "yes (no waves)" : "no"});
  sec.add(t);
}

Table everyPoint(const SurfaceWavesConfig& c, const std::vector<SurfaceWaveSummary>& points,
                 const std::string& title) {
  Table t;
  t.title = title;
  t.columns = {"point",      "runs",      "f/2 wave in windows", "standing mode",  "amplitude (d)",
               "lambda (d)", "share f/2", "detector (seeds)",    "RMS(v_x) (m/s)", "e_eff"};
  for (const SurfaceWaveSummary& s : points)
    t.rows.push_back({pointName(c, s.point), fmt::format("{}/{}", s.ok, s.seeds),
                      fmt::format("{:.0f} % of {}", 100 * s.wave_fraction, s.windows),
                      std::to_string(s.standing_mode), format(s.amplitude_d),
                      s.waves() ? format(s.wavelength_d, 1) : "–", format(s.share),
                      fmt::format("{}/{}", s.detector_votes, s.ok), format(s.rms_vx, 4),
                      format(s.e_eff, 3)});
  return t;
}

}  // namespace

void reportSurfaceWaves(const SurfaceWavesConfig& c, const SurfaceWavesResults& r, Report& report) {
  // Spearman's rho is undefined below 3 variants with an onset or when their ranks tie.
  const std::string rho = std::isfinite(r.rank_correlation) ? formatNumber(r.rank_correlation, 2)
                          : r.ranked_variants < 3           ? "undefined (fewer than 3)"
                                                  : "undefined (the onsets or the e_eff tie)";
  report.summary = fmt::format(
      "- Runs: {} ({} failed), {:.0f} CPU-s.\n"
      "- Box modes or Faraday waves (width scan): {}. Decided by the two widest boxes with a "
      "wave: wavelengths within 2 sigma of each other mean a Faraday wave, a wavelength ratio "
      "nearer the widths' ratio than 1 a box mode.\n"
      "- Does the onset follow the layer's dissipation: Spearman rank correlation of Gamma_c "
      "with e_eff over the {} variants with an onset: {}.\n"
      "- Deficiency factor r_x = RMS(v_x)_dry / RMS(v_x)_wet (mean ± standard error over "
      "points): {} with waves in either layer, {} without (the noise floor).\n",
      r.runs.size() + c.continuumPoints().size(), r.failed_runs, r.cpu_seconds, r.width_verdict,
      r.ranked_variants, rho, format(r.r_x_waves), format(r.r_x_control));
  report.section("Method", method(c));
  addOnset(c, r, report);
  ReportSection& spectra = report.section(
      "Spectra of the strongest waves",
      "For each variant, the run with the largest f/2 amplitude: its surface over the last "
      "cycles, its power per mode split by temporal response, and the temporal spectrum of its "
      "dominant mode.");
  addSpectra(r, spectra);
  ReportSection& widths = report.section(
      "Box modes or Faraday waves",
      "A Faraday wave has a wavelength of its own, set by the layer and the drive; a box mode's "
      "wavelength is a fraction of the box (2 W / m with walls, W / m periodic).");
  addWidthScan(c, r, widths);
  ReportSection& dispersion = report.section(
      "Dispersion relation against published granular Faraday waves",
      "Umbanhowar & Swinney (Physica A 288, 344 (2000)) fitted the wavelengths of vertically "
      "vibrated layers as lambda / H = 1.0 + 1.1 (f sqrt(H/g))^(-1.32 +- 0.03), H the layer "
      "depth (the fit as it is widely quoted; its coefficients were not checked against the "
      "paper's text for this report). Melo, "
      "Umbanhowar & Swinney (PRL 72, 172 (1994)) found the standing waves at f/2 from a "
      "critical acceleration with a gravity-wave-like dispersion and a cutoff at the grain "
      "size, the critical value about 2.5 g (Umbanhowar, Melo & Swinney, Physica A 249, 1 "
      "(1998)); Bizon et al. (PRL 80, 57 (1998)) reproduced the patterns with event-driven "
      "hard spheres from about 2.5 g. Clement, Vanel, Rajchenbach & Duran (PRE 53, 2972 "
      "(1996)) found a peak instability with a dispersion relation in quasi-2D layers, as the "
      "paper's model is (as Luding et al., EPL 36, 247 (1996) summarise it; the papers' full "
      "texts were not checked). These are 3D or quasi-2D layers of many more "
      "grains per wavelength; a 2D layer of hard disks is compared on the same axes for its "
      "trend, not its prefactor.");
  addDispersion(c, r, dispersion);
  addDissipation(c, r, report);
  addMomentumRatio(r, report);
  addContinuum(c, r, report);
  ReportSection& all = report.section("Every point", "");
  all.add(everyPoint(c, r.onset, "Onset scan (base box)"));
  all.add(everyPoint(c, r.widths, "Width scan"));
  all.add(everyPoint(c, r.depths, "Depth scan"));
}

}  // namespace granwave
