#pragma once
// Local bond-orientational (hexatic) order of disks in the x-z plane (Halperin & Nelson,
// PRL 41, 121 (1978); Strandburg, RMP 60, 161 (1988)), for the crystal / amorphous
// distinction of the stability diagram (paper Fig. 3, triangles and circles).
//
// For particle j with neighbours k (centre distance below cutoff, default 1.2 d) at bond
// angles theta_jk,
//
//     psi6_j = (1/n_j) sum_k exp(6 i theta_jk).
//
// On a triangular lattice every bond angle is a multiple of 60 degrees, so |psi6_j| = 1 for
// every particle, at the surface and the walls too. On a square lattice the four bonds at
// 90 degrees give 1 - 1 + 1 - 1 = 0. With n bonds at independent random angles |psi6_j| is
// the mean step of an n-step unit random walk, W_n / n = 0.64, 0.53, 0.45, 0.40, 0.37 for
// n = 2 .. 6 (Borwein, Straub, Wan, Zudilin, Can. J. Math. 64, 961 (2012)).
//
// Cutoff 1.2 d: the first shell of a triangular packing is at d, the second at sqrt(3) d =
// 1.73 d; the diagonal of a square packing is at sqrt(2) d = 1.41 d. 1.2 d keeps the first
// shell of a layer dilated by up to 20 % and excludes the rest.
//
// Global order: the mean of the moduli, <|psi6_j|>, over particles with at least
// min_neighbours neighbours. It asks whether each particle sits in a hexagonal cage,
// whatever the orientation of its crystallite; the modulus of the mean, |<psi6_j>|, also
// requires one orientation over the whole layer and would call a polycrystal (grains tilted
// against each other, common in a layer compacted against side walls) disordered. It is
// reported too.
//
// Particles with fewer than min_neighbours (default 3) bonds are left out of both means. One
// bond gives |psi6| = 1 whatever the structure, and two give |cos 3 (theta_1 - theta_2)|,
// which is 1 for a straight chain as for a hexagonal cage; three bonds not in a half-plane
// is also the least that cages a disk in 2D. This matters for sparse random packings: random
// sequential addition (coverage 0.55) has about 2 bonds per particle within 1.2 d, and
// counting the 1- and 2-bond particles raises its <|psi6|> from ~0.55 to ~0.65, next to the
// crystal threshold.
#include <complex>
#include <span>
#include <vector>

namespace granwave {

struct HexaticOptions {
  double cutoff = 1.2;     // neighbour distance in d (see above)
  int min_neighbours = 3;  // fewer bonds: left out of the global means (see above)
};

struct HexaticOrder {
  std::vector<std::complex<double>> psi6;  // per particle (0 without neighbours)
  std::vector<int> neighbours;             // n_j
  double mean_abs_psi6 = 0;                // <|psi6_j|> over counted particles
  double abs_mean_psi6 = 0;                // |<psi6_j>| over counted particles
  int counted = 0;                         // particles with n_j >= min_neighbours
};

// Neighbour lists: for each particle, the indices of the others with centre distance
// < cutoff (m), via a cell list. periodic_x uses the minimum image over `width` (m; ignored
// without periodic_x); z is never periodic (a driven layer). Lists are sorted.
std::vector<std::vector<int>> neighboursWithin(std::span<const double> x, std::span<const double> z,
                                               double cutoff, double width, bool periodic_x);

// Throws std::invalid_argument if x and z differ in length, diameter <= 0, cutoff <= 0, or
// periodic_x with width <= 0.
HexaticOrder hexaticOrder(std::span<const double> x, std::span<const double> z, double width,
                          double diameter, bool periodic_x, const HexaticOptions& options = {});

}  // namespace granwave
