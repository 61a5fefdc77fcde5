#pragma once
// Crystal / amorphous / liquid-like state of a vibrated layer (paper Sec. III, stability
// diagram Fig. 3: triangles, circles, crosses; coarse-graining.md, "Solid vs fluid").
//
// The paper classifies by eye: "crystalline and amorphous states are distinguished from
// whether the particles are caged in a crystalline or a random configuration. In a
// liquid-like state, the particles can move freely with respect to their neighbors." Here
// the two questions are measured on snapshots taken at one drive phase in consecutive cycles
// c = 0 .. K-1 (same particle order in every snapshot).
//
// (a) Mobility relative to the neighbours. With Delta r_j = r_j(c+1) - r_j(c) (minimum image
//     in x if periodic) and N_j the neighbours of j at cycle c (centre distance below
//     neighbour_cutoff),
//
//         delta_j = | Delta r_j - (1/|N_j|) sum_{k in N_j} Delta r_k |.
//
//     Subtracting the neighbours' mean displacement removes the collective motion (the whole
//     layer flying, the drift of a crystallite) and keeps the motion out of the cage.
//     Particles without neighbours are measured against the whole layer's mean displacement.
//     M = <delta_j> over particles and pairs of consecutive cycles, in d.
//
// (b) Hexatic order: <|psi6_j|> (HexaticOrder.hpp), averaged over the K snapshots.
//
//     liquid-like  if M > mobility_threshold,
//     crystal      else if <|psi6|> > crystal_threshold,
//     amorphous    otherwise.
//
// Why these numbers.
//   mobility_threshold = 0.15 d. A caged particle cannot move relative to its neighbours by
//   more than its free length; a particle that can has left the cage. The 2D dynamic
//   Lindemann criterion puts melting where the relative displacement of neighbours reaches
//   <|Delta u_j - Delta u_k|^2> = 2 gamma_m a^2 with gamma_m = 0.033 (Bedanov, Gadiyak,
//   Lozovik, Phys. Lett. A 109, 289 (1985); Zahn, Lenke, Maret, PRL 82, 2721 (1999)). For
//   independent displacements with s^2 = <|Delta u|^2> the pair measure is 2 s^2, so
//   s^2 = gamma_m a^2 at melting, and the neighbour-mean measure above has
//   <delta^2> = s^2 (1 + 1/n); with n = 6 and Gaussian
//   displacements <delta> = (sqrt(pi)/2) sqrt(gamma_m (7/6)) a = 0.17 a. One drive cycle
//   (T = 0.1 s) holds hundreds of collisions, far beyond the rattling time, so this is the
//   long-time regime the criterion refers to. The spacing a >= d; 0.15 d rounds down, so a
//   layer just past melting is not called solid.
//   crystal_threshold = 0.7. Random bond angles give <|psi6|> = W_n / n = 0.37 - 0.53 for
//   n = 3 - 6 bonds (HexaticOrder.hpp); a triangular lattice with Gaussian position noise of
//   rms sigma per component has bond-angle noise ~ sqrt(2) sigma / a and
//   |psi6| ~ exp(-36 sigma^2 / a^2), which is 0.7 at sigma = 0.1 a, the Lindemann scale of a
//   crystal near melting. 0.7 therefore keeps hot crystals and rejects random packings.
//   neighbour_cutoff = 1.5 d (mobility only): the first minimum of g(r) in dense disk fluids
//   lies at 1.4 - 1.5 d, so the first shell of a layer dilated in flight is still included,
//   while the second shell of a triangular packing (sqrt(3) d = 1.73 d) is not.
#include <string_view>
#include <vector>

#include "coarse_grain/HexaticOrder.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

enum class LayerState { crystal, amorphous, liquid_like };

std::string_view toString(LayerState state);  // "crystal", "amorphous", "liquid-like"

struct StateOptions {
  HexaticOptions hexatic;            // psi6 neighbours: 1.2 d, >= 3 bonds
  double neighbour_cutoff = 1.5;     // d, initial neighbours for the mobility
  double mobility_threshold = 0.15;  // d, mean relative displacement per cycle
  double crystal_threshold = 0.7;    // <|psi6|>
};

struct StateResult {
  LayerState state = LayerState::amorphous;
  double mean_relative_displacement_d = 0;    // M / d
  double mean_collective_displacement_d = 0;  // |<Delta r_j>_j| / d, averaged over pairs
  double mean_abs_psi6 = 0;                   // <|psi6|>, averaged over snapshots
  double abs_mean_psi6 = 0;                   // |<psi6>|, averaged over snapshots
  int cycles = 0;                             // K
};

// Mean relative displacement <delta_j> (m) between two snapshots of the same particles,
// neighbours taken in `before`. Throws std::invalid_argument if the particle counts differ.
double meanRelativeDisplacement(const Snapshot& before, const Snapshot& after, double width,
                                bool periodic_x, double neighbour_cutoff);

// `same_phase_cycles[c]`: the layer at one drive phase in consecutive cycles, K >= 2.
// Throws std::invalid_argument for K < 2, differing particle counts, or non-positive
// diameter.
StateResult classifyState(const std::vector<Snapshot>& same_phase_cycles, double width,
                          double diameter, bool periodic_x, const StateOptions& options = {});

}  // namespace granwave
