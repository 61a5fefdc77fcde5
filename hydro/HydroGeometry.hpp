#pragma once
// The container and drive every continuum solver shares (GranularHydro1D, GranularHydro2D),
// and the numerical parameters of their discrete operators (docs/hydro.md, "Sensitivity to
// the numerical parameters").

namespace granwave::hydro {

struct HydroGeometry {
  int cells = 100;       // N, cells of equal mass
  double height = 0.06;  // L_z, plate to lid, m
  double gravity = 9.81;
  double amplitude = 0;  // A, m
  double omega = 0;      // rad/s
  double ramp_time = 0;  // s: the amplitude grows from 0 to A over this time (quintic ramp)

  // The plate z_b(t) = A r(t) sin(omega t) and its derivatives, r the ramp.
  double plateHeight(double t) const;
  double plateVelocity(double t) const;
  double plateAcceleration(double t) const;
};

// How the plate and the lid meet the layer's boundary node (docs/hydro.md, "Walls").
// Spring: a stiff unilateral repulsion within wall_contact_range of the wall, with a dashpot
// (two regularisation parameters). Hard: a hard wall, contact and lift-off found as events
// (the node lands completely inelastically and is held at the wall while the wall must push
// on it; it is released when that reaction would pull): no parameter.
enum class WallModel { Spring, Hard };

// The numerical parameters of the discrete operator. None of them is physics: the answers
// (periods, fronts, the centre-of-mass trajectory) must not move when one is halved or
// doubled, and docs/hydro.md ("Sensitivity to the numerical parameters") shows that they do not.
struct HydroRegularisation {
  // c2 of the artificial viscosity q = rho c2 du^2 in compressing cells (Caramana, Shashkov &
  // Whalen, J. Comput. Phys. 144, 70 (1998), the 1D quadratic form): it spreads a shock the
  // physical viscosity does not resolve over a few cells; its work heats the cell.
  double quadratic_viscosity = 0.25;
  // The plate and the lid push on the boundary node within `wall_contact_range` diameters of
  // them, with the stress P_c (p/wall_contact_stiffness)^3 at a penetration p into that range
  // (P_c = rho_cp g sigma, the weight per unit length of one close-packed row).
  double wall_contact_range = 0.05;
  double wall_contact_stiffness = 0.01;
  WallModel walls = WallModel::Spring;  // Hard: the two above are not used
  // Close packing as a constraint: the closures see the density through
  // rho_eff = rho_max - d s((rho_max - rho)/d), s(x) = (x + sqrt(x^2 + 4))/2, with d this
  // fraction of the close-packed density (GranularHydro1D::cellView).
  double packing_width = 1e-4;
  // Added to theta where the closures take its powers (in g sigma): only a guard against an
  // iterate whose exp(s) underflows; 15 orders of magnitude below the coldest state a run reaches.
  double temperature_floor = 1e-30;
};

}  // namespace granwave::hydro
