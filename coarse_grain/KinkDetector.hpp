#pragma once
// Period-doubling kinks (paper Sec. III, stability diagram Fig. 3, filled diamonds; Melo et
// al. PRL 75, 3838 (1995); Butzhammer et al. PRE 92, 032214 (2015)).
//
// Above the period-doubling threshold (Gamma ~ 3.7 for the inelastic bouncing ball) the layer
// takes off every other cycle from a high or a low trajectory. Two regions of the layer may
// pick opposite choices: two flat domains oscillating in antiphase at f/2, joined by a kink.
// At a fixed drive phase the surface of each domain is then alternately high and low from
// one cycle to the next, with opposite signs on the two sides of the kink.
//
// From surfaces h_c(x) at one phase in consecutive cycles c = 0 .. K-1 (SurfaceProfile, same
// columns) the period-2 difference
//
//     D(x) = <(-1)^c (h_c(x) - h_{c+1}(x))>_{c = 0 .. K-2}       (= h_0 - h_1 for K = 2)
//
// is twice the f/2 component of the surface at that phase; averaging over pairs lowers the
// grain-scale noise (see below). The local period-2 phase is s(x) = sign D(x) with a dead
// band: s = 0 where |D| < dead_band. Domains are runs of equal non-zero s; runs narrower than
// min_domain are dropped as noise, then neighbouring runs of equal sign (separated only by
// dead band or dropped runs) are merged. A kink is the boundary between two neighbouring
// domains of opposite sign (and, with periodic x, between the last and the first). Its
// position is the zero crossing of D, linearly interpolated between column centres (the
// middle of the first and last crossing if noise gives several).
//
// Flat domains. The antinodes of a subharmonic standing surface wave also have opposite
// period-2 signs. What distinguishes a kink is that its domains are plateaus. With P the
// median of s D over a domain, its plateau columns are those with s D >= P/2 (this leaves
// out the kink's own transition columns) and its flatness is F = 1 - std/mean of s D over
// them. A plateau with relative noise eps has F ~ 1 - eps; a sinusoidal antinode (half wave)
// has F = 0.73 - 0.77 whatever its amplitude, up to 0.82 only when its crest-to-trough height
// is below 2 dead bands (1 d) and the dead band clips it. Both domains of a kink need
// F >= min_flatness (0.8), so kinks need eps below ~0.15: average over about 10 cycles
// (noise on D: sigma_h sqrt(4K - 6) / (K - 1), sqrt(2) sigma_h for K = 2). A domain of only
// 3 columns next to a kink of width ~d is not flat by this measure (F ~ 0.7).
//
// Only period-2 kinks are detected; the period-tripling kinks of wet experiments (Butzhammer
// et al. 2015) would need the f/3 component instead.
#include <vector>

#include "coarse_grain/SurfaceProfile.hpp"

namespace granwave {

struct KinkOptions {
  // |D| below which the local phase is undecided, in d. 0.5 d: the period-2 height
  // difference of antiphase domains is of the order of the plate amplitude (A = 5 d at
  // f = 10 Hz, Gamma = 4) and stays above d up to f ~ 20 Hz, while the grain-scale noise of a
  // single difference of two rough surfaces is ~0.4 d (sigma_h ~ 0.3 d per column), less
  // after averaging over cycle pairs.
  double dead_band = 0.5;
  // Narrowest domain in d. A domain must be wider than the kink itself (a few d in
  // experiments) and than the runs that grain-scale noise forms by chance (one or two
  // columns); 3 d.
  double min_domain = 3.0;
  // Least domain flatness F (see above): a plateau with relative noise eps has F ~ 1 - eps
  // (0.85 on average at eps = 0.1), sinusoidal antinodes F <= 0.77 (up to 0.82 for
  // crest-to-trough < 1 d). 0 switches the flatness test off.
  double min_flatness = 0.8;
};

struct KinkDomain {
  int first_column = 0;          // inclusive; with periodic x a domain may wrap (last < first)
  int last_column = 0;           // inclusive
  int sign = 0;                  // +1: h_0 above h_1 there, -1: below
  double width_d = 0;            // domain width / d
  double mean_difference_d = 0;  // <s D> / d over the domain
  double flatness = 0;           // F = 1 - std/mean of s D over the plateau columns
};

struct KinkResult {
  bool detected = false;
  std::vector<double> kink_x;       // m, lab-frame x of each kink (in [0, L_x))
  std::vector<double> difference;   // m, D per column
  std::vector<int> phase_sign;      // s per column (-1, 0, +1)
  std::vector<KinkDomain> domains;  // in order of x, after dropping and merging
};

// Two profiles at the same phase in consecutive cycles.
KinkResult detectKinks(const SurfaceProfile& cycle_a, const SurfaceProfile& cycle_b,
                       const KinkOptions& options = {});

// Profiles at one phase in K >= 2 consecutive cycles. Throws std::invalid_argument for fewer
// than 2 profiles or profiles of different geometry.
KinkResult detectKinks(const std::vector<SurfaceProfile>& same_phase_cycles,
                       const KinkOptions& options = {});

}  // namespace granwave
