// The lattice placement fills exactly the sites scene/PlacementCapacity.hpp counts, so a scene
// the check admits is placed, and one particle more is refused by the check (exit 2), not by
// the placement after the program has started.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "particles/EdSimulation.hpp"
#include "particles/InitialState.hpp"
#include "scene/PlacementCapacity.hpp"
#include "scene/SceneParser.hpp"

namespace granwave {
namespace {

Scene latticeScene(double width, double height, bool periodic_x, long long count) {
  Scene s;
  s.contact.restitution = RestitutionKind::Dry;
  s.container.width = width;
  s.container.height = height;
  s.container.periodic_x = periodic_x;
  s.drive.frequency = 0;  // a plate at rest: any height is a valid box
  s.drive.gamma.reset();
  s.initial.placement = InitialPlacement::Lattice;
  s.particles.count = static_cast<int>(count);
  return s;
}

double closestPair(const InitialCondition& ic) {
  double closest = 1e300;
  for (std::size_t i = 0; i < ic.x.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      closest = std::min(closest, std::hypot(ic.x[i] - ic.x[j], ic.z[i] - ic.z[j]));
  return closest;
}

// The capacity placed without overlap inside the walls; one particle more refused.
void expectLatticeFillsItsCapacity(double width, double height, bool periodic) {
  SCOPED_TRACE(std::to_string(width) + " x " + std::to_string(height));
  const double d = latticeScene(width, height, periodic, 1).particles.diameter;
  const long long capacity = TriangularLattice(width, height, d, periodic).capacity();
  ASSERT_GT(capacity, 1);
  const Scene full = latticeScene(width, height, periodic, capacity);
  EXPECT_NO_THROW(validateScene(full, "full.toml"));
  const InitialCondition ic = initialCondition(full, engineConfig(full));
  ASSERT_EQ(static_cast<long long>(ic.x.size()), capacity);
  EXPECT_GE(closestPair(ic), d);
  EXPECT_LE(*std::max_element(ic.z.begin(), ic.z.end()), height - 0.5 * d);
  if (!periodic) {
    EXPECT_LE(*std::max_element(ic.x.begin(), ic.x.end()), width - 0.5 * d);
  }
  EXPECT_THROW(validateScene(latticeScene(width, height, periodic, capacity + 1), "over.toml"),
               SceneError);
}

TEST(InitialState, LatticePlacementFillsExactlyTheCapacityTheSceneCheckAdmits) {
  // The paper's box, a periodic one, and widths at and just off a whole number of diameters.
  expectLatticeFillsItsCapacity(0.1, 0.04, false);
  expectLatticeFillsItsCapacity(0.1, 0.04, true);
  expectLatticeFillsItsCapacity(0.02, 0.01, false);
  expectLatticeFillsItsCapacity(0.020001, 0.0117, false);
  expectLatticeFillsItsCapacity(0.0199999, 0.013, true);
}

}  // namespace
}  // namespace granwave
