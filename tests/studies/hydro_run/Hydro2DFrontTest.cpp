// A flat 2D layer's impact fronts are the 1D layer's: a column of the flat 2D run, seen in the
// lab frame on the coarse-graining rows (LabFrame.hpp), gives the fronts the 1D run gives, by
// the same detector (coarse_grain/WaveFront), at the same phases and speeds.
#include <gtest/gtest.h>

#include <cmath>

#include "hydro/HydroSimulation2D.hpp"
#include "scene/SceneParser.hpp"
#include "studies/hydro_run/Hydro2DRun.hpp"
#include "studies/hydro_run/HydroModel.hpp"
#include "studies/hydro_run/HydroRun.hpp"
#include "studies/hydro_run/LabFrame.hpp"

namespace granwave {
namespace {

// Column 0 of a 2D window as the 1D run's phases (cell centres, node-averaged vertical
// velocity, the boundary nodes as the layer's edges).
hydro::HydroResult columnAsLayer(const hydro::Hydro2DResult& r, int cells, int period) {
  hydro::HydroResult one;
  one.period = period;
  one.periodic = true;
  for (const hydro::Hydro2DPhase& ph : r.window) {
    hydro::HydroPhase p;
    p.time = ph.time;
    p.plate_height = ph.plate_height;
    p.plate_velocity = ph.plate_velocity;
    p.center_of_mass_height = ph.center_of_mass_height;
    p.layer_bottom = ph.node_z[0];
    p.layer_top = ph.node_z[static_cast<std::size_t>(cells)];
    for (int k = 0; k < cells; ++k) {
      const auto K = static_cast<std::size_t>(k);
      p.z.push_back(0.5 * (ph.node_z[K] + ph.node_z[K + 1]));
      p.u.push_back(ph.velocity_z[K]);
      p.theta.push_back(ph.theta[K]);
      p.area_fraction.push_back(ph.area_fraction[K]);
      p.pressure.push_back(ph.pressure[K]);
    }
    one.window.push_back(std::move(p));
  }
  return one;
}

}  // namespace

TEST(Hydro2DFront, FlatLayerHasThe1DImpactFrontsAndSpeeds) {
  // The paper's dry scene, periodic in x, 100 cells, rtol 1e-6 (both), 50 phases per cycle;
  // the 2D layer flat (no perturbation) on two columns. The solvers differ by their error
  // control only (trajectories within 5e-5 of the excursion, Hydro2DFlatLayerTest): the
  // speeds must agree within the 1 %, the phases exactly.
  const Scene s = parseSceneFile(
      std::string(GRANWAVE_SOURCE_DIR) + "/scenes/paper-dry.toml",
      {"hydro.cells=100", "run.phases_per_cycle=50", "run.duration=1.2",
       "container.periodic_x=true", "hydro.rtol=1e-6", "hydro.perturbation=0", "hydro.columns=2"});
  const HydroRunContent one = runHydroScene(s, "paper-dry.toml", nullptr);
  ASSERT_TRUE(one.periodic);
  const SceneDerived dv = derive(s);
  const auto op = hydro2DOperator(s, dv);
  hydro::Hydro2DRunOptions o = hydro2DRunOptions(s, dv);
  o.cycles = static_cast<int>(one.cycles);
  o.window_cycles = one.windowCycles();
  const hydro::Hydro2DResult two = hydro::HydroSimulation2D(*op, o).run();
  const PhaseProfiles lab = labFrameProfiles(
      s, dv, columnAsLayer(two, op->cells(), static_cast<int>(one.period)), o.samples_per_cycle);
  int compared = 0;
  for (const FrontEpisode& a : one.lab.fronts) {
    if (!a.from_impact || !std::isfinite(a.speed)) continue;
    bool found = false;
    for (const FrontEpisode& b : lab.fronts) {
      if (b.first_phase != a.first_phase || !b.from_impact) continue;
      found = true;
      EXPECT_EQ(b.last_phase, a.last_phase);
      EXPECT_NEAR(b.speed / a.speed, 1.0, 0.01) << "front from phase " << a.first_phase;
      RecordProperty("speed_1d", std::to_string(a.speed));
      RecordProperty("speed_2d", std::to_string(b.speed));
    }
    EXPECT_TRUE(found) << "no 2D front from phase " << a.first_phase;
    ++compared;
  }
  EXPECT_GT(compared, 0);
}

}  // namespace granwave
