#pragma once
// The impact front's passage through the layer's mass. In a deep layer the front decelerates
// all the way from the packed bottom (tens of m/s) to the dilute top (a few m/s): the 40-row
// continuum layer's front crosses its lowest 2.5 cm in 0.25 ms and its next 4 cm in 4.5 ms. One
// straight line through such a track (ImpactFrontTracker's fit) is an average whose value
// depends on where the track ends, and that end moves with every detail of the top (halving the
// continuum's artificial viscosity ends it 1.9 ms earlier and raises the fit by 10 %, while the
// track itself, its arrival times at fixed heights, moves by 1-4 %). A transit speed is defined
// by the layer, not by the track's ends: the mean speed, Delta z / Delta t, between the
// passages of the front through two fractions of the layer's mass (the share of the layer's mass
// below the front at each tracked phase, interpolated linearly between phases).
#include "coarse_grain/ImpactFrontTracker.hpp"

namespace granwave {

// The mass fractions every front summary reports transits between (the summaries' `velocity
// front` lines, the wave-fronts study, the continuum-sensitivity study's default): 0.1-0.5 the
// dense lower half of the layer, 0.5-0.9 its upper part. The ends are left out: below a tenth
// the front is still the underside compacting against the plate, above nine tenths the dilute
// top, where a front's position is ill-defined.
inline constexpr double kReportedFractions[3] = {0.1, 0.5, 0.9};

struct FrontTransit {
  bool reached = false;   // the track passes both fractions
  bool resolved = false;  // at least min_points tracked phases lie between the two passages
  double from_time = 0, to_time = 0;      // s, on the track's clock (TrackedFront::time)
  double from_height = 0, to_height = 0;  // m
  double speed = 0;                       // m/s when resolved, else NaN
  // When not resolved: the passage took less than (phases between + 1) phase intervals, so the
  // speed is above (to_height - from_height) / that time (m/s); else NaN.
  double speed_lower_bound = 0;
};

// The share of the layer's mass below `height` at a phase: the trapezoidal integrals of the
// density over the profile's heights (rows without a finite density count as empty).
double massFractionBelow(const FrontProfiles& p, int phase, double height);

// The front's transit from mass fraction `from` to `to` (0 <= from < to <= 1). A front first seen
// above a fraction (it crossed the packed bottom within a phase) passed it during the phase
// interval before its first tracked phase, where the layer then had that share of its mass
// below: unresolved, with the bound (height difference) / (phase intervals spanned).
FrontTransit frontTransit(const FrontProfiles& p, const TrackedFront& front, double phase_dt,
                          double from, double to, const FrontTrackOptions& o = {});

}  // namespace granwave
