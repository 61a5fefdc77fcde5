// The wave-fronts study's table of the impact fronts' transits through the layer's mass against
// N (docs/studies.md, section 4): the particles over the sweep's seeds (the whole run, and its
// period-2 windows aligned on their strong impact) beside the continuum, with the periods of
// both, so the deep layers are compared by a speed the layer defines (the mean
// speed between two fractions of its mass, coarse_grain/FrontTransit.hpp) and not by a straight
// line whose value depends on where the track ends.
#include <fmt/format.h>

#include <cmath>

#include "studies/wave_fronts/WaveFrontsReport.hpp"

namespace granwave {

namespace {

std::string periodsCell(const std::vector<int>& periods) {
  if (periods.empty()) return "no run";
  std::string out;
  for (int p : periods) out += (out.empty() ? "" : ", ") + (p > 0 ? fmt::format("{}T", p) : "-");
  return out;
}

// The continuum's transit over the particles': their ratio with the particles' relative error
// (the continuum's transit is deterministic; without a particle error the ratio has none), or
// how a bound compares with a speed.
std::string ratioCell(const TransitSpeeds& hydro, const TransitSpeeds& particles) {
  const Measurement& h = hydro.speed;
  const Measurement& p = particles.speed;
  if (h.valid() && p.valid() && p.value > 0) {
    const double r = h.value / p.value;
    return format({r, r * p.error / p.value});
  }
  if (h.valid() && std::isfinite(particles.lower_bound))
    return h.value < particles.lower_bound
               ? fmt::format("< {:.2f} (the continuum is slower than the particles' bound)",
                             h.value / particles.lower_bound)
               : "undetermined (the particles give only a bound)";
  if (p.valid() && std::isfinite(hydro.lower_bound))
    return hydro.lower_bound > p.value
               ? fmt::format("> {:.2f} (the continuum's bound exceeds the particles' speed)",
                             hydro.lower_bound / p.value)
               : "undetermined (the continuum gives only a bound)";
  return "–";
}

// The period-2 windows' transits, "0.1-0.5 / 0.5-0.9", or why there are none.
std::string period2Cell(const SweepPoint& p) {
  if (p.period2_seeds == 0) return "no period-2 windows";
  return fmt::format("{} / {} ({} of {} seeds)", transitCell(p.tracked_period2.transit[0]),
                     transitCell(p.tracked_period2.transit[1]), p.period2_seeds, p.tracked_seeds);
}

}  // namespace

void transitDepthTable(const WaveFrontsConfig& c, const WaveFrontsResults& r, ReportSection& s) {
  Table t;
  t.title = "Impact fronts' transits through the layer's mass against N";
  t.columns = {"N",
               "law",
               "ED periods (seeds)",
               "ED mass 0.1-0.5 (m/s)",
               "ED mass 0.5-0.9 (m/s)",
               "ED period-2 windows (m/s)",
               "hydro period",
               "hydro mass 0.1-0.5 (m/s)",
               "hydro mass 0.5-0.9 (m/s)",
               "hydro / ED, 0.1-0.5",
               "hydro / ED, 0.5-0.9"};
  for (std::size_t i = 0; i < c.counts.size(); ++i)
    for (int law = 0; law < kLaws; ++law) {
      const SweepPoint& p = r.n_sweep[law][i];
      const VelocityFronts& ed = p.tracked;
      const VelocityFronts& hy = p.hydro_tracked;
      t.rows.push_back(
          {std::to_string(c.counts[i]), kLawNames[law], periodsCell(p.seed_periods),
           transitCell(ed.transit[0]), transitCell(ed.transit[1]), period2Cell(p),
           p.hydro_ok ? (p.hydro_period > 0 ? fmt::format("{}T", p.hydro_period) : "not periodic")
                      : "failed",
           transitCell(hy.transit[0]), transitCell(hy.transit[1]),
           ratioCell(hy.transit[0], particleTransit(p, 0)),
           ratioCell(hy.transit[1], particleTransit(p, 1))});
    }
  s.add(std::move(t));
  s.addText(fmt::format(
      "A transit is the impact front's mean speed between its passages through two fractions of "
      "the layer's mass (the share of the mass below the front at each tracked phase, "
      "interpolated between phases): 0.1-0.5 the dense lower half, 0.5-0.9 the upper part. "
      "Unlike the straight-line fit above it does not depend on where the track ends, which "
      "moves with every detail of a deep layer's dilute top. Particles: seeds {} at {} phases "
      "per cycle, each transit's error the std over the tracker's block bootstrap, combined over "
      "a run's impact fronts (a period-2 layer's weak and strong impacts together) and over seeds "
      "(their scatter enlarges it). A layer that alternates a weak and a strong impact pools "
      "episodes of both parities in its 2-cycle window, where the velocity jump may not be "
      "tracked: its period-2 windows, each aligned on its strong impact (simulate "
      "--state-fields), give the transits beside them (both impacts together), and the ratio "
      "is taken against these where the whole run has none. "
      "A front that passes both fractions within fewer than three "
      "phases gives only a lower bound (the heights of the fractions over the phase intervals "
      "spanned); a finer sampling (`[sweep] phases_per_cycle`) resolves it. The continuum's "
      "transits are deterministic (at period 2 the mean of its two impacts): the ratio's error "
      "is the particles'.",
      fmt::join(c.sweep_seeds, ", "), c.sweep_phases));
}

}  // namespace granwave
