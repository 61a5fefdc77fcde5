#pragma once
// The fronts launched by the layer's impacts on the plate, as the paper reports them (Sec. IV,
// Fig. 5): after the 'weak' and after the 'strong' impact of a period-2 layer. Within one run
// (a window of whole cycles) the impact fronts are ranked by their peak T~_g/T0: the weaker
// peak is the weak impact. A layer of period 1 has equivalent impacts; with a single impact
// front in the window it stands for both.
#include <vector>

#include "coarse_grain/PhaseProfiles.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

struct ImpactFronts {
  Measurement weak, strong;                               // m/s, lab frame
  Measurement all;                                        // combined over the run's impact fronts
  double weak_start = kNoPhase, strong_start = kNoPhase;  // t/T within the window
  int weak_phase = -1, strong_phase = -1;  // their first phase index in the window (one run)
  int count = 0;
  static constexpr double kNoPhase = -1;
};

// The run's fronts (p.fronts), their starts at p's phases.
ImpactFronts impactFronts(const PhaseProfiles& p);
// Over seeds (or repeated runs): each field combined with granwave::combine.
ImpactFronts combineImpactFronts(const std::vector<ImpactFronts>& runs);

// The paper's collision time (Sec. IV, Fig. 6a): t/T of the lowest centre-of-mass point,
// one per cycle of the window (reduced to [0, 1)).
std::vector<double> centerOfMassMinimumPhases(const PhaseProfiles& p, int cycles_in_window);

}  // namespace granwave
