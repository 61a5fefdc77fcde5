#pragma once
// How many particles the initial placements (particles/InitialState.hpp) can put in a box,
// so that the scene check admits exactly what placement fits:
//  - "lattice" in a box with a floor: a triangular lattice resting on the bottom, rows filled
//    from below. Its sites are defined here once; the placement walks the same rows.
//  - "lattice" in a fully periodic box: a square lattice over the whole box.
//  - "random": random sequential adsorption, which jams at a covered area fraction of 0.547
//    (Feder, J. Theor. Biol. 87, 237 (1980); Hinrichsen, Feder and Jossang, J. Stat. Phys. 44,
//    793 (1986)): no random placement without overlap gets beyond it, and the placement's
//    finite number of attempts stops somewhat before it.
#include <cmath>

namespace granwave {

inline constexpr double kRandomJammingCoverage = 0.547;

// The rows of the resting triangular lattice: row r at height z(r) holds sites(r) particles,
// from x = x0(r) in steps of spacing.
struct TriangularLattice {
  TriangularLattice(double width, double height, double diameter, bool periodic_x);

  int rows() const { return rows_; }
  double z(int r) const { return 0.5 * d_ + r * row_height_; }
  double x0(int r) const { return first_x_ + (r % 2) * 0.5 * spacing_; }
  double spacing() const { return spacing_; }
  int sites(int r) const;
  long long capacity() const;

 private:
  double d_, spacing_, row_height_, first_x_, last_x_;
  int rows_;
};

// The square lattice of a fully periodic box for n particles: columns ceil(sqrt(n W / H)),
// rows ceil(n / columns); it fits if both spacings are at least one diameter.
struct SquareLattice {
  SquareLattice(long long n, double width, double height);
  int columns, rows;
  double spacing_x, spacing_z;
  bool fits(double diameter) const { return spacing_x >= diameter && spacing_z >= diameter; }
};

}  // namespace granwave
