#pragma once
// Crystal / amorphous / liquid-like within one drive cycle: the second solid criterion
// (docs/classification.md, "Two solid criteria").
//
// The paper labels its layers "by inspection of the collective motion of particles during the
// free-flying period": what one flight or one compression looks like. The bond criterion
// (StateClassifier.hpp) asks instead whether the layer keeps its neighbours over 15 cycles. A
// layer that is pressed against the lid and ordered in every cycle, but remixed between
// compressions, is a crystal to the eye and liquid-like to the bonds. This criterion judges
// each cycle on its own, from the snapshots at its sampled phases:
//
//   coordination z_k  = mean number of neighbours closer than `neighbour_cutoff` per
//                       particle, at phase k;
//   order psi_k       = <|psi6|> at phase k (HexaticOrder.hpp);
//   the cycle's most compact phase k* = argmax_k z_k (the compression, or any phase of a
//                       layer that flies as one slab);
//   the cycle is      liquid-like if z_k* < caged_coordination (even at its densest the
//                       layer is no rigid network: its particles move freely),
//                     crystal     else if psi_k* > crystal_threshold,
//                     amorphous   otherwise.
// The layer's label is the most frequent over the K cycles (ties: crystal, amorphous,
// liquid-like in that order, the order of a layer freezing), with the share of each.
//
// Why these numbers.
//   neighbour_cutoff = 1.2 d: the first shell of a dense packing, the psi6 bonds.
//   caged_coordination = 4: Maxwell's counting for a rigid network of frictionless disks,
//   z_iso = 2 D = 4 contacts per disk in 2D (jammed packings have z >= 4: O'Hern, Silbert,
//   Liu & Nagel, PRE 68, 011306 (2003)). Near-contacts within 1.2 d stand in for contacts.
//   A triangular slab of R rows has z = 6 - 4/R (5.7 for the paper's 12 rows), a gas 0.
//   crystal_threshold = 0.7: as the bond criterion (StateClassifier.hpp).
//
// Also reported: the particles pressed against the lid (within lid_gap of it, centre above
// lid - d/2 - lid_gap), the largest number at one sampled phase of a cycle, averaged over
// cycles; the lid sits at plate + container height (the box moves as one).
#include <vector>

#include "coarse_grain/HexaticOrder.hpp"
#include "coarse_grain/StateClassifier.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

struct WithinCycleOptions {
  HexaticOptions hexatic;           // psi6 neighbours: 1.2 d, >= 3 bonds
  double neighbour_cutoff = 1.2;    // d, coordination shell
  double caged_coordination = 4.0;  // mean neighbours at the most compact phase
  double crystal_threshold = 0.7;   // <|psi6|>
  double lid_gap = 0.1;             // d, a particle this close to the lid is pressed on it
};

struct WithinCycleResult {
  LayerState state = LayerState::amorphous;                         // most frequent per-cycle label
  double crystal_share = 0, amorphous_share = 0, liquid_share = 0;  // of the K cycles
  double coordination = 0;    // z at each cycle's most compact phase, mean over cycles
  double psi6 = 0;            // <|psi6|> there, mean over cycles
  double compact_phase = 0;   // t/T of the most compact phase, most frequent over cycles
  double lid_row = 0;         // particles on the lid at the fullest phase, mean over cycles
  double lid_row_cycles = 0;  // share of cycles with at least one particle on the lid
  int cycles = 0;             // K
};

// Mean number of neighbours closer than `cutoff` (m) per particle (0 for no particles).
double meanCoordination(const Snapshot& s, double cutoff, double width, bool periodic_x);

// `cycles[c][k]`: the layer at sampled phase k (k / S of the cycle) of cycle c, K >= 1 cycles
// of S >= 1 phases each, in order. `container_height` puts the lid at plate + height.
// Throws std::invalid_argument for no cycles, cycles of different sizes, or a non-positive
// diameter.
WithinCycleResult classifyWithinCycles(const std::vector<std::vector<Snapshot>>& cycles,
                                       double width, double container_height, double diameter,
                                       bool periodic_x, const WithinCycleOptions& options = {});

}  // namespace granwave
