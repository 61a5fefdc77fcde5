#pragma once
// The impact fronts of a run by the velocity-jump tracker (coarse_grain/ImpactFrontTracker.hpp),
// the tracker that stays right in deep layers (docs/fields.md, "Impact fronts by the velocity
// jump"): per run the speed of its impact fronts with errors from a bootstrap over its blocks of
// cycles (particles) or the fit (hydro), the Rankine-Hugoniot speed from the states either side,
// and, for fronts too fast for the sampling, a lower bound; over seeds, their combination.
#include <string>
#include <vector>

#include "coarse_grain/FieldsReader.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

// The fronts' transit speed between two fractions of the layer's mass (coarse_grain/
// FrontTransit.hpp), over the window's impact fronts: the resolved transits combined (particles:
// each with the std of its transit over the tracker's block bootstrap; the continuum: their
// mean, with no statistical error), the smallest lower bound of those crossing within fewer
// phases than a speed needs, and counts.
struct TransitSpeeds {
  Measurement speed;  // m/s
  double lower_bound = NAN;
  int fronts = 0, reached = 0, resolved = 0;
};

struct VelocityFronts {
  Measurement speed;  // m/s, lab frame: the run's resolved impact fronts combined
  // After the weak and after the strong impact of the window (particles): the T~g-peak impact
  // fronts ranked by their peak T~g/T0 (ImpactFronts.hpp), each matched to the velocity-jump
  // episode starting within 3 phases of it; invalid when that episode is unresolved, dropped
  // or missing. A window with one T~g-peak impact front has it stand for both.
  Measurement weak, strong;
  Measurement jump_speed;  // m/s, Rankine-Hugoniot [rho v] / [rho] over the same fronts
  int episodes = 0, resolved = 0;
  double lower_bound = NAN;  // m/s: the smallest bound of the unresolved fronts
  std::string why_none;      // empty when `speed` is valid
  // Between consecutive kReportedFractions (coarse_grain/FrontTransit.hpp): the dense lower
  // half and the upper part of the layer.
  TransitSpeeds transit[2];
};

// A transit for a table cell: the speed (and the smallest bound of the fronts too fast for one,
// if any), else "> B (within fewer phases than a speed needs)", else why there is none.
std::string transitCell(const TransitSpeeds& t);

// The index of the start in `starts` nearest to `phase` on a cycle of `phases`, if no more
// than `within` phases away; else -1.
int nearestEpisode(const std::vector<int>& starts, int phase, int phases, int within);

// Particles: time between phases from the run's frequency and window; errors from a bootstrap
// over its blocks of cycles.
VelocityFronts velocityFronts(const FieldsRecord& particles);
// Hydro (lab-frame profiles), `phase_dt` the time between its phases (s).
VelocityFronts velocityFronts(const PhaseProfiles& p, double phase_dt);
// Over seeds: the speeds (and weak, strong) combined (granwave::combine: the seed scatter
// enlarges the error),
// lower bounds by their smallest, the reasons kept when no seed has a speed.
VelocityFronts combineVelocityFronts(const std::vector<VelocityFronts>& seeds);

}  // namespace granwave
