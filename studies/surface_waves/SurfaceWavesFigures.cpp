#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "studies/surface_waves/SurfaceWavesReport.hpp"

namespace granwave {

namespace {

const char* kColors[] = {"tab:orange", "tab:blue", "tab:green", "tab:red",   "tab:purple",
                         "tab:brown",  "tab:pink", "tab:gray",  "tab:olive", "tab:cyan"};

// h(x, t) - <h>_x of the example's newest cycles, as an image over x / d and t / T.
Figure spaceTime(const ExampleSpectrum& e) {
  Figure f;
  f.title = fmt::format("{}{}", "Surface h(x, t) - <h>: ", e.label);
  f.xlabel = "x / d";
  f.ylabel = "t / T (newest cycles)";
  Image im;
  im.nx = e.columns;
  im.ny = e.records;
  for (int r = 0; r < e.records; ++r) {
    double mean = 0;
    for (int i = 0; i < e.columns; ++i) mean += e.recent_height[r * e.columns + i];
    mean /= e.columns;
    for (int i = 0; i < e.columns; ++i)
      im.values.push_back((e.recent_height[r * e.columns + i] - mean) / e.diameter);
  }
  im.x0 = 0;
  im.x1 = e.width_d;
  im.y0 = 0;
  im.y1 = static_cast<double>(e.records) / e.records_per_cycle;
  im.label = "(h - <h>) / d";
  im.cmap = "RdBu_r";
  f.image.push_back(std::move(im));
  f.caption =
      "The layer's surface (half-bulk area-fraction crossing above the plate) at every "
      "recorded phase of the run's last cycles: a Faraday wave shows as a pattern whose crests "
      "and troughs swap every cycle.";
  return f;
}

Figure spatialSpectrum(const ExampleSpectrum& e) {
  Figure f;
  f.title = fmt::format("{}{}", "Power per surface mode: ", e.label);
  f.xlabel = "wavenumber k d";
  f.ylabel = "power (d^2)";
  f.yscale = "log";
  const double d2 = e.diameter * e.diameter;
  std::vector<double> k, sub, harm, broad;
  for (std::size_t m = 1; m < e.wavenumber.size(); ++m) {
    k.push_back(e.wavenumber[m] * e.diameter);
    sub.push_back(std::max(e.power_subharmonic[m] / d2, 1e-8));
    harm.push_back(std::max(e.power_harmonic[m] / d2, 1e-8));
    broad.push_back(std::max(e.power_broadband[m] / d2, 1e-8));
  }
  f.series.push_back(lineSeries(k, sub, "locked at f/2 (subharmonic)", "tab:red"));
  f.series.push_back(lineSeries(k, harm, "locked at f (harmonic)", "tab:blue"));
  f.series.push_back(lineSeries(k, broad, "not locked (broadband)", "tab:gray"));
  f.caption =
      "Mean over windows of 10 cycles; locked powers bias-corrected by the noise (floored at "
      "1e-8 d^2 for the log scale).";
  return f;
}

Figure temporalSpectrum(const ExampleSpectrum& e) {
  Figure f;
  f.title = fmt::format("{}{}", "Temporal power of the dominant mode: ", e.label);
  f.xlabel = "frequency / f";
  f.ylabel = "power (d^2)";
  f.yscale = "log";
  std::vector<double> p;
  for (double v : e.temporal_power) p.push_back(std::max(v / (e.diameter * e.diameter), 1e-8));
  Series s = lineSeries(e.frequency_over_f, p, "", "tab:purple");
  s.style = "step";
  f.series.push_back(s);
  f.legend = false;
  f.caption = "Bins of f / 10: a Faraday wave peaks at 1/2 and 3/2, a harmonic one at 1 and 2.";
  return f;
}

// Umbanhowar & Swinney's fit, lambda / H = 1.0 + 1.1 (f sqrt(H / g))^(-1.32).
double umbanhowarSwinney(double fh) { return 1.0 + 1.1 * std::pow(fh, -1.32); }

}  // namespace

void addSpectra(const SurfaceWavesResults& r, ReportSection& sec) {
  for (const ExampleSpectrum& e : r.examples) {
    sec.add(spaceTime(e));
    sec.add(spatialSpectrum(e));
    sec.add(temporalSpectrum(e));
  }
}

void addDispersion(const SurfaceWavesConfig& c, const SurfaceWavesResults& r, ReportSection& sec) {
  Figure f;
  f.title = "Dispersion: lambda / H against f sqrt(H / g)";
  f.xlabel = "f sqrt(H / g)";
  f.ylabel = "lambda / H";
  f.xscale = "log";
  f.yscale = "log";
  Table t;
  t.title = "Wavelength against depth and frequency";
  t.columns = {"variant",
               "rows (H/d)",
               "f (Hz)",
               "f sqrt(H/g)",
               "f/2 wave in windows",
               "lambda (d)",
               "lambda / H",
               "Umbanhowar & Swinney lambda / H",
               "share f/2"};
  const double g = 9.81;
  std::vector<double> xs;
  for (std::size_t v = 0; v < c.variants.size(); ++v) {
    std::vector<double> x, y, e;
    for (const SurfaceWaveSummary& s : r.depths) {
      if (s.point.variant != static_cast<int>(v)) continue;
      const double H = s.point.rows * c.diameter;
      const double fh = s.point.frequency * std::sqrt(H / g);
      xs.push_back(fh);
      const bool wave = s.waves() && s.wavelength_d.valid();
      t.rows.push_back({c.variants[v].name, std::to_string(s.point.rows),
                        formatCompact(s.point.frequency), formatNumber(fh, 3),
                        fmt::format("{:.0f} %", 100 * s.wave_fraction),
                        wave ? format(s.wavelength_d, 1) : "–",
                        wave ? formatNumber(s.wavelength_d.value / s.point.rows, 2) : "–",
                        formatNumber(umbanhowarSwinney(fh), 2), format(s.share)});
      if (!wave) continue;
      x.push_back(fh);
      y.push_back(s.wavelength_d.value / s.point.rows);
      e.push_back(s.wavelength_d.error / s.point.rows);
    }
    if (x.empty()) continue;
    Series pts = errorSeries(x, y, e, c.variants[v].name, kColors[v % 10]);
    pts.linestyle = "none";
    pts.marker = "o";
    f.series.push_back(pts);
  }
  if (!xs.empty()) {
    const double lo = *std::min_element(xs.begin(), xs.end()) * 0.8;
    const double hi = *std::max_element(xs.begin(), xs.end()) * 1.25;
    std::vector<double> x, y;
    for (int i = 0; i <= 40; ++i) {
      x.push_back(lo * std::pow(hi / lo, i / 40.0));
      y.push_back(umbanhowarSwinney(x.back()));
    }
    Series us = lineSeries(x, y, "Umbanhowar & Swinney (2000), 3D experiment", "black");
    us.linestyle = "--";
    f.series.push_back(us);
  }
  f.caption =
      "Points: the f/2 standing wave's wavelength (mean over windows and seeds) where the point "
      "waves (half its windows or more, seeds pooled, with a wave); H = rows x d. Line: the fit to "
      "vertically vibrated layers "
      "of bronze spheres in Umbanhowar & Swinney, Physica A 288, 344 (2000).";
  sec.add(f);
  sec.add(t);
}

void addWidthScan(const SurfaceWavesConfig& c, const SurfaceWavesResults& r, ReportSection& sec) {
  Table t;
  t.title = fmt::format("Box width and boundary at f = {} Hz, Gamma = {}",
                        formatCompact(c.width_frequency), formatCompact(c.width_gamma));
  t.columns = {"variant",       "boundary",        "W (d)",      "f/2 wave in windows",
               "standing mode", "lambda (d)",      "W / lambda", "amplitude (d)",
               "share f/2",     "detector (seeds)"};
  for (const SurfaceWaveSummary& s : r.widths) {
    const bool wave = s.waves() && s.wavelength_d.valid();
    t.rows.push_back(
        {c.variants[s.point.variant].name, s.point.periodic ? "periodic" : "walls",
         formatCompact(s.point.width_d), fmt::format("{:.0f} %", 100 * s.wave_fraction),
         std::to_string(s.standing_mode), wave ? format(s.wavelength_d, 1) : "–",
         wave ? formatNumber(s.point.width_d / s.wavelength_d.value, 2) : "–",
         format(s.amplitude_d), format(s.share), fmt::format("{}/{}", s.detector_votes, s.ok)});
  }
  t.caption = fmt::format("Verdict: {}", r.width_verdict);
  sec.add(t);
}

std::string pointName(const SurfaceWavesConfig& c, const SurfaceWavePoint& p) {
  return fmt::format("{}, W = {} d {}, {} rows, f = {} Hz, Gamma = {}", c.variants[p.variant].name,
                     formatCompact(p.width_d), p.periodic ? "periodic" : "walls", p.rows,
                     formatCompact(p.frequency), formatCompact(p.gamma));
}

}  // namespace granwave
