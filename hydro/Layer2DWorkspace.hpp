#pragma once
// The intermediate quantities of GranularHydro2D's right-hand side, per cell, face and node,
// on any scalar type (hydro/Scalar.hpp), and the grid's neighbour indexing. Internal to the 2D
// operator (included by its sources only).
#include <vector>

#include "hydro/GranularHydro2D.hpp"
#include "hydro/Scalar.hpp"

namespace granwave::hydro {

// Cells (i, k) and faces (i, k) (the right face of cell (i, k)) are numbered i N + k, nodes
// (i, j) i (N + 1) + j. A missing neighbour (a side wall) is -1.
struct ColumnGrid {
  int Nx = 0, N = 0;
  bool periodic = true;
  int left(int i) const { return i > 0 ? i - 1 : (periodic ? Nx - 1 : -1); }
  int right(int i) const { return i + 1 < Nx ? i + 1 : (periodic ? 0 : -1); }
  int cell(int i, int k) const { return i * N + k; }
  int node(int i, int j) const { return i * (N + 1) + j; }
  // The column at offset d from i (periodic wrap, or mirrored at a side wall: the ghost
  // column beyond a wall is the image of the one inside it).
  int mirrored(int i, int d) const {
    int c = i + d;
    if (periodic) return ((c % Nx) + Nx) % Nx;
    if (c < 0) c = -1 - c;
    if (c >= Nx) c = 2 * Nx - 1 - c;
    return c < 0 ? 0 : (c >= Nx ? Nx - 1 : c);
  }
};

template <class S>
struct GranularHydro2D::Workspace {
  Workspace(int Nx, int N, bool periodic)
      : grid{Nx, N, periodic},
        len(Nx * N),
        mass(Nx * N),
        rho(Nx * N),
        rho_eff(Nx * N),
        theta(Nx * N),
        zc(Nx * N),
        heat(Nx * N),
        heat_r(Nx * N),
        exchange(Nx * N),
        spin(Nx * N),
        local(Nx * N),
        flux(Nx * N),
        flux_du(Nx * N),
        h(Nx * N),
        fu(Nx * N),
        zx(Nx * (N + 1)),
        face_slope(Nx * (N + 1)),
        drift(Nx * (N + 1)),
        fw(Nx * (N + 1)) {}
  ColumnGrid grid;
  // Cells: length, mass per unit width (floored), density mass/length, the density and
  // temperature the closures see, centre height, power into the cell (W per unit depth), the
  // same for the rotational energy (advection), rough particles' collisional rates, closures.
  std::vector<S> len, mass, rho, rho_eff, theta, zc, heat, heat_r, exchange, spin;
  std::vector<LocalState<S>> local;
  // Faces: mass flux to the right (kg/s per unit depth), its derivative by u, height, force on
  // u (N per unit depth).
  std::vector<S> flux, flux_du, h, fu;
  // Nodes: the interface's slope dz/dx (central), its slope between the node's column and
  // the next (per face, as the faces), its vertical drift (Layer2DState.hpp, interfaceDrift),
  // force on w.
  std::vector<S> zx, face_slope, drift, fw;
  // Per column: the plate's and the lid's stress, losses and elastic stress (energy rates).
  struct Wall {
    S plate_stress, lid_stress, plate_loss, lid_loss, plate_elastic, lid_elastic;
  };
  std::vector<Wall> walls = std::vector<Wall>(grid.Nx);
  S side_loss{};
};

template <int Colours>
struct GranularHydro2D::JetWorkspace {
  JetWorkspace(int Nx, int N, bool periodic, int n) : w(Nx, N, periodic), U(n), dU(n) {}
  Workspace<Jet<Colours>> w;
  std::vector<Jet<Colours>> U, dU;
};

}  // namespace granwave::hydro
