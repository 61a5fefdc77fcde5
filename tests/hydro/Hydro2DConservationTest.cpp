// The 2D layer's mass is exact to round-off whatever the solver does: the time-integrated
// mass fluxes are the unknowns, and each leaves one cell for its neighbour.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "Hydro2DTestSupport.hpp"
#include "hydro/HydroSimulation2D.hpp"
#include "hydro/Layer2DStart.hpp"

using namespace granwave::hydro;
using test::kD;
using test::kMass;

namespace {

// The paper's dry scene on a 2D layer of 8 columns over 24 d with the column masses
// perturbed by 5 % RMS, spread over the box and falling onto the plate.
Hydro2DResult perturbedRun(bool periodic, int cycles) {
  const ConstitutiveModel m =
      test::beadModel(RestitutionClosure::dry(0.1), RestitutionClosure::dry(0.1));
  HydroGeometry g = test::drivenBox(20);
  g.ramp_time = 0.2;
  const int columns = 8;
  const GranularHydro2D op(g, {columns, 24 * kD, periodic}, m,
                           perturbedCellMasses(columns, 20, 300 * kMass / (30 * kD), 0.05, 42));
  Hydro2DRunOptions o;
  o.rtol = 1e-6;
  o.samples_per_cycle = 50;
  o.cycles = cycles;
  o.window_cycles = cycles;
  return HydroSimulation2D(op, o).run();
}

}  // namespace

TEST(Hydro2DConservation, MassIsExactToRoundOffOverARun) {
  // The total mass sum_ik mu0 dx + (Phi_i-1,k - Phi_ik) telescopes: what is left is the
  // round-off of 160 additions of numbers of the column's size, ~1e-16 each. Two cycles: the
  // perturbed columns fall, land and exchange mass under the rising drive (the third cycle
  // this test once ran added only time: 38 s of the sanitizer build's CI).
  for (bool periodic : {true, false}) {
    const Hydro2DResult r = perturbedRun(periodic, 2);
    EXPECT_LT(r.mass_drift, 1e-13) << (periodic ? "periodic" : "side walls");
    char drift[32];
    std::snprintf(drift, sizeof drift, "%.3g", r.mass_drift);
    RecordProperty(periodic ? "mass_drift_periodic" : "mass_drift_walls", drift);
  }
}
