#pragma once
// The vertical remap of GranularHydro2D's layers (an arbitrary Lagrangian-Eulerian step).
//
// The layers are material: mass leaves a layer only sideways, through the faces between
// columns, never up or down. Where the flow near the free surface is two-dimensional a layer
// can therefore empty locally (horizontal outflow through both faces of a cell under a column
// rising faster than its neighbours), and the emptied cell's temperature equation, divided by
// its mass, then fails (docs/hydro.md, "Vertical remap"). The remap moves the interfaces of
// every column back to its mass shares and carries the fields with the mass:
//
//   - cell masses: column i's layer k gets mu'_ik = M_i L_k / M, with M_i the column's mass,
//     L_k the layer's (invariant: mass moves only inside a layer) and M the whole layer's, so
//     both every column's and every layer's mass are kept; the mass fluxes Phi are set so that
//     mu0 + (Phi_i-1,k - Phi_ik)/dx is mu' (a periodic recurrence with a solution because the
//     layer totals are kept; its free constant keeps each layer's mean Phi);
//   - nodes: z'_j where the column's cumulative mass (piecewise linear in z, the cells
//     uniform) reaches sum_k<j mu'_ik; plate and surface nodes stay where they are;
//   - temperatures (and rotational temperatures): mass-weighted means over the overlaps in the
//     column's mass coordinate, so the internal energy sum mu theta is kept exactly;
//   - vertical velocities: interpolated linearly in the mass coordinate at the new nodes;
//     horizontal velocities: averaged over the overlaps in the layer-mass fraction (the mean of
//     the face's two columns' fractions).
//
// Averaging velocities changes the kinetic energy (and the lumped potential energy a little):
// the difference of the lab-frame energy (GranularHydro2D::labEnergy) is given to the
// internal energy in proportion to it, so the remap keeps mass and energy exactly and
// temperatures positive (it is refused if the difference exceeds half the internal energy).
#include <vector>

#include "hydro/GranularHydro2D.hpp"

namespace granwave::hydro {

// The smallest mu_ik / (M_i L_k / M) over the cells: 1 for a layer at its mass shares, 0 for
// a cell emptied.
double thinnestLayerShare(const GranularHydro2D& op, const double* U);

// Remaps the layer state U at time t as above. Returns the energy moved into heat (J per unit
// depth; negative if the averaging raised the mechanical energy). Throws std::runtime_error if
// a column has no mass or the energy difference would take half the internal energy.
double remapLayers(const GranularHydro2D& op, double t, std::vector<double>& U);

}  // namespace granwave::hydro
