#include "scene/PlacementCapacity.hpp"

#include <algorithm>

namespace granwave {

// Sites one part in 10^6 further apart than a diameter: touching neighbours would start in
// contact, which the engine reads as an overlap.
TriangularLattice::TriangularLattice(double width, double height, double diameter, bool periodic_x)
    : d_(diameter),
      spacing_(diameter * (1.0 + 1e-6)),
      row_height_(spacing_ * std::sqrt(3.0) / 2.0),
      first_x_(periodic_x ? 0.0 : 0.5 * diameter),
      last_x_(periodic_x ? width - spacing_ : width - 0.5 * diameter),
      rows_(height < diameter
                ? 0
                : static_cast<int>(std::floor((height - diameter) / row_height_)) + 1) {}

int TriangularLattice::sites(int r) const {
  const double span = last_x_ + 1e-12 - x0(r);
  return span < 0 ? 0 : static_cast<int>(std::floor(span / spacing_)) + 1;
}

long long TriangularLattice::capacity() const {
  long long n = 0;
  for (int r = 0; r < rows_; ++r) n += sites(r);
  return n;
}

SquareLattice::SquareLattice(long long n, double width, double height)
    : columns(std::max(1, static_cast<int>(std::ceil(std::sqrt(n * width / height))))),
      rows(static_cast<int>((n + columns - 1) / columns)),
      spacing_x(width / columns),
      spacing_z(height / std::max(1, rows)) {}

}  // namespace granwave
