#pragma once
// The impact front tracked by the jump of the vertical velocity (docs/fields.md, "Impact fronts
// by the velocity jump"). When the layer lands on the plate, the material below the front
// already moves with the plate while the material above still falls: across the front v_z drops
// from v_behind (the fastest-rising row of the layer) to v_ahead (the fastest-falling row above
// it). The front at a phase is where v_z(z) falls through the midpoint (v_behind + v_ahead) / 2,
// linear between rows; of several such crossings, the one with the largest drop over two rows
// either side. A front needs v_behind - v_ahead >= min_jump and must lie inside the layer (rows
// with density >= min_density). Unlike the peak of T~_g (WaveFront.hpp) this does not need the
// front to be hot: in a deep, dense layer the impact is carried by a compaction front at nearly
// constant granular temperature, and the velocity jump is what moves.
//
// An episode is a run of consecutive phases (cyclic over the window) with a front that does not
// move down by more than one row spacing per phase, starting within `impact_rows` rows of the
// bottom of the layer, or higher when every row below it already moves behind the front and
// the bottom row was still ahead of it one phase before: the impact then crossed the packed
// bottom of the layer within that phase (a deep layer of hard grains passes an impact on at
// once), which the episode records as a bulk crossing with a lower bound on its speed; its speed is
// the slope of a straight line through height vs time from the last phase before the front has
// risen by a row spacing (earlier phases are the layer's dilute underside compacting against the
// plate, not propagation). With fewer than `min_points` phases the front crossed the layer faster
// than the sampling resolves: the episode then carries only a lower bound on its speed, (layer
// thickness) / (phases + 1) dt.
//
// Rankine-Hugoniot check (mass conservation across a moving discontinuity): with the states a
// few rows behind (b) and ahead (a) of the front, s = (rho_b v_b - rho_a v_a) / (rho_b - rho_a)
// (e.g. Landau & Lifshitz, Fluid Mechanics, Sec. 84). It needs a density jump that stands out
// of the noise, which the hydro solver's shocks have and a dense particle layer may not.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "coarse_grain/PhaseFields.hpp"

namespace granwave {

struct FrontTrackOptions {
  double min_density = 0.1;  // rows of the layer (area fraction, or the density's unit)
  double min_jump = 0.2;     // m/s: v_behind - v_ahead of a front
  int state_offset = 2;      // rows between the front and the Rankine-Hugoniot states
  double impact_rows = 4;    // an episode starts this close to the layer's bottom (rows)
  int min_points = 3;        // phases for a fitted speed
};

// Profiles [phase][z], heights ascending: the rows of a fixed grid (z holds nz heights) or
// the cells of a Lagrangian solution that move with the mass (z holds [phase][z] heights).
// "Rows" in the options are then cells.
struct FrontProfiles {
  int phases = 0, nz = 0;
  std::vector<double> z;                  // m
  std::vector<double> density, velocity;  // [phase][z]; velocity in m/s (NaN: no data)
  double at(const std::vector<double>& v, int phase, int j) const {
    return v[static_cast<std::size_t>(phase) * nz + j];
  }
  double height(int phase, int j) const {
    return z.size() == static_cast<std::size_t>(nz) ? z[j] : at(z, phase, j);
  }
};

// The lab-frame profiles of phase fields on rows at heights `z`, as the tracker reads them:
// the area fraction as the density, v~_z as the velocity.
FrontProfiles frontProfiles(const PhaseFields& fields, const std::vector<double>& z);

// The front at one phase.
struct FrontCrossing {
  bool found = false;
  double height = 0;                               // m
  double velocity_behind = 0, velocity_ahead = 0;  // m/s, the extremes defining the midpoint
  double layer_bottom = 0, layer_top = 0;          // m, lowest and highest layer row
  double spacing = 0;                              // m, mean row spacing in the layer
  double jump_speed = 0;                           // m/s, Rankine-Hugoniot (NaN: no density jump)
};

FrontCrossing locateFront(const FrontProfiles& p, int phase, const FrontTrackOptions& o = {});

struct TrackedFront {
  int first_phase = 0, points = 0;
  std::vector<double> time, height;  // s since the window's start (unwrapped), m
  double speed = 0, fit_error = 0;   // m/s (NaN when unresolved)
  double speed_lower_bound = 0;      // m/s, when unresolved (fewer than min_points phases)
  bool resolved = false;
  double jump_speed = 0, jump_speed_spread = 0;  // mean and std of the Rankine-Hugoniot speeds
  // An impact that crossed the packed bottom of a deep layer within one phase is first seen
  // high above the bottom: the height it crossed in that phase (m) and the speed that takes,
  // (that height) / dt (m/s), a lower bound; 0 and NaN for a front first seen at the bottom.
  double bulk_crossing = 0, bulk_speed_lower_bound = 0;
  // Block bootstrap (trackWithBootstrap): std of the speed over resamples, and the share of
  // resamples in which this episode was found.
  double bootstrap_error = 0, bootstrap_found = 0;
};

// Impact fronts of the window; phase_dt the time between phases (s).
std::vector<TrackedFront> trackFronts(const FrontProfiles& p, double phase_dt,
                                      const FrontTrackOptions& o = {});

// The block bootstrap's defaults.
inline constexpr int kBootstrapResamples = 200;
inline constexpr std::uint64_t kBootstrapSeed = 15;

// The standard deviation (n - 1) of a property over the resamples that gave it: the bootstrap
// error trackWithBootstrap attaches to a speed, and a caller to what it bootstraps through
// `visit`. NaN for fewer than two values.
double bootstrapSpread(const std::vector<double>& values);

// The same, with errors from a bootstrap over independent blocks of cycles: each resample
// draws as many blocks as there are, with replacement, averages their profiles (velocity
// weighted by density) and tracks again; an episode's resampled speed is that of the resampled
// episode starting nearest to it (within 3 phases). The draw is a fixed 64-bit Mersenne Twister
// sequence (index = draw mod blocks), so the errors are the same on every build.
// `visit`, if given, sees every match: the resampled profiles, the index of the pooled
// episode and the resampled front matched to it, so a caller can bootstrap any other
// property of the front (FrontTransit) over the same resamples.
using ResampleVisitor = std::function<void(const FrontProfiles& resampled, std::size_t episode,
                                           const TrackedFront& matched)>;
std::vector<TrackedFront> trackWithBootstrap(const FrontProfiles& pooled,
                                             const std::vector<FrontProfiles>& blocks,
                                             double phase_dt, const FrontTrackOptions& o = {},
                                             int resamples = kBootstrapResamples,
                                             std::uint64_t seed = kBootstrapSeed,
                                             const ResampleVisitor& visit = {});

}  // namespace granwave
