#pragma once
// Wave fronts after the impacts of the layer on the plate (paper Sec. IV, Fig. 5;
// docs/fields.md, "Definitions"). At each phase the front is the height of the peak of
// T~_g(z) where T~_g / T0 > 0.5 (T0 = m v0^2 / 2), refined between rows by a parabola through the
// peak and its neighbours. Only rows of the layer count (row area fraction >=
// layer_min_area_fraction): the few ballistic particles of the dilute gas above the layer have T~_g
// of several T0 and would otherwise be taken for a front (granwave's resolution; docs/fields.md). A
// front episode is a maximal run of consecutive phases (cyclic over the window) with a front; its
// speed is the slope of a straight-line fit of front height vs time. The uncertainty combines the
// fit's standard error with the spread of the same fit over independent blocks of cycles:
// sqrt(s_fit^2 + s_blocks^2), s_blocks = std(block slopes)/sqrt(blocks). The speed relative to the
// gas ahead subtracts the mean vertical velocity of the layer above the front (rows more than one
// diameter above it, weighted by area fraction), averaged over the episode. Fronts are waves
// launched by an impact: an episode counts as one only if it starts within `impact_max_rows` rows
// of the plate; hot spots elsewhere (the top of the layer during free flight) are kept but flagged.
#include <vector>

#include "coarse_grain/PhaseFields.hpp"

namespace granwave {

struct FrontOptions {
  double threshold = 0.5;                // T~_g / T0 above which a peak is a front
  double layer_min_area_fraction = 0.1;  // rows searched for the peak
  int min_points = 3;                    // phases needed for a fit
  double gas_min_area_fraction = 0.05;   // rows counted as gas ahead of the front
  double impact_max_rows = 4;            // rows (diameters) above the plate
};

struct FrontEpisode {
  int first_phase = 0, last_phase = 0;      // window phases (last may wrap: last < first)
  std::vector<double> time;                 // s since the start of the window (unwrapped)
  std::vector<double> height;               // m, lab frame
  double peak_temperature = 0;              // max T~_g / T0 over the episode
  double speed = kNaN, speed_error = kNaN;  // m/s, lab frame
  double fit_error = kNaN, block_spread = kNaN;
  int blocks_used = 0;
  double gas_velocity_ahead = kNaN;  // m/s
  double speed_relative = kNaN;      // speed - gas_velocity_ahead
  double start_above_plate = kNaN;   // m, first front height minus the plate height
  bool from_impact = true;           // starts near the plate (see above)
};

// Front height per phase (NaN where no front), and the peak T~_g/T0 per phase.
std::vector<double> frontHeights(const PhaseFields& f, double z0, double dz, double T0,
                                 const FrontOptions& o, std::vector<double>* peak = nullptr);

// Episodes with speeds; `blocks` may be empty (then block_spread is NaN and the error is the
// fit error alone). `phase_dt` is the time between phases (1/(M f)).
// `plate_height` [phase] (m) may be empty: every episode then counts as from an impact.
std::vector<FrontEpisode> frontEpisodes(const PhaseFields& pooled,
                                        const std::vector<PhaseFields>& blocks, double z0,
                                        double dz, double T0, double phase_dt,
                                        const FrontOptions& o = {},
                                        const std::vector<double>& plate_height = {});

}  // namespace granwave
