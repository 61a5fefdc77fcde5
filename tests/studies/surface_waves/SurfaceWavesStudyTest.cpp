// The surface-waves study's plan for the 2D continuum ([continuum]): which runs it asks for,
// and the keys it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "studies/contract/StudyFile.hpp"
#include "studies/surface_waves/SurfaceWavesStudy.hpp"
#include "tests/h5/ScratchDir.hpp"
#include "tests/studies/contract/StudyErrorMessage.hpp"

namespace {

// A study file of the paper's two laws in the 120 d base box at 10 Hz, with `continuum` as its
// [continuum] section.
class SurfaceWavesStudyPlan : public ::testing::Test {
 protected:
  granwave::StudyFile file(const std::string& continuum) const {
    const std::string scenes = std::string(GRANWAVE_SOURCE_DIR) + "/scenes/";
    const std::filesystem::path p = scratch_.path() / "s.toml";
    std::ofstream(p) << "[study]\nkind = \"surface-waves\"\n[scenes]\ndry = \"" << scenes
                     << "paper-dry.toml\"\nwet = \"" << scenes
                     << "paper-wet.toml\"\n[grid]\nfrequencies = [10.0]\ngammas = [3.0, 4.0]\n"
                     << "[widths]\nwidths = [120.0]\nboundaries = [\"periodic\"]\n"
                     << "[depths]\nrows = [10]\nfrequencies = [10.0]\n"
                     << continuum;
    return granwave::StudyFile::load(p.string());
  }
  granwave::testing::ScratchDir scratch_;
};

using granwave::testing::contains;
using granwave::testing::studyError;

}  // namespace

TEST_F(SurfaceWavesStudyPlan, ContinuumPointsPlanA2DHydroRunBesideTheParticlesAtTheSameDrive) {
  granwave::StudyFile f = file(
      "[continuum]\nvariants = [\"wet\"]\nwidths = [60.0]\ngammas = [3.0, 4.0]\n"
      "seeds = [1, 2, 3]\ncycles = 50\ncells = 24\ncolumns = 10\n");
  const granwave::SurfaceWavesStudy study(f);
  int hydro = 0, particles_at_60 = 0;
  for (const granwave::RunRequest& q : study.plan()) {
    const double width_d = q.scene.container.width / q.scene.particles.diameter;
    if (q.kind == granwave::RunKind::Hydro) {
      ++hydro;
      EXPECT_EQ(q.scene.hydro.dimensions, 2) << q.label;
      EXPECT_EQ(q.scene.hydro.columns, 10) << q.label;
      EXPECT_EQ(q.scene.hydro.cells, 24) << q.label;
      EXPECT_TRUE(q.scene.container.periodic_x) << q.label;
      EXPECT_NEAR(width_d, 60.0, 1e-9) << q.label;
      EXPECT_NEAR(q.scene.run.duration * q.scene.drive.frequency, 50.0, 1e-9) << q.label;
    } else if (std::abs(width_d - 60.0) < 1e-9) {
      ++particles_at_60;  // the particles at the continuum's points, one per particle seed
      EXPECT_TRUE(q.scene.container.periodic_x) << q.label;
      EXPECT_EQ(q.scene.particles.count, 600) << q.label;
    }
  }
  EXPECT_EQ(hydro, 2 * 3);            // two Gamma, three continuum seeds
  EXPECT_EQ(particles_at_60, 2 * 2);  // two Gamma, the particles' two default seeds
}

TEST_F(SurfaceWavesStudyPlan, ContinuumBetweenSideWallsPlansWalledRunsOfBothModels) {
  granwave::StudyFile f = file(
      "[continuum]\nvariants = [\"wet\"]\nwidths = [60.0]\nboundaries = [\"periodic\", "
      "\"walls\"]\ngammas = [4.0]\n");
  const granwave::SurfaceWavesStudy study(f);
  int hydro_walls = 0, hydro_periodic = 0, particles_walls = 0;
  for (const granwave::RunRequest& q : study.plan()) {
    const double width_d = q.scene.container.width / q.scene.particles.diameter;
    if (std::abs(width_d - 60.0) > 1e-9) continue;
    const bool walls = !q.scene.container.periodic_x;
    if (q.kind == granwave::RunKind::Hydro) {
      ++(walls ? hydro_walls : hydro_periodic);
      EXPECT_NE(q.label.find(walls ? " walls " : " periodic "), std::string::npos) << q.label;
    } else if (walls) {
      ++particles_walls;
    }
  }
  EXPECT_EQ(hydro_walls, 1);  // one Gamma, one continuum seed
  EXPECT_EQ(hydro_periodic, 1);
  EXPECT_EQ(particles_walls, 2);  // the particles' two default seeds
}

TEST_F(SurfaceWavesStudyPlan, WithoutContinuumVariantsNoHydroRunIsPlanned) {
  granwave::StudyFile f = file("");
  const granwave::SurfaceWavesStudy study(f);
  for (const granwave::RunRequest& q : study.plan())
    EXPECT_EQ(q.kind, granwave::RunKind::Particles) << q.label;
}

TEST_F(SurfaceWavesStudyPlan, ContinuumKeysOutOfRangeAreRefusedNamingTheKey) {
  const std::string wet = "[continuum]\nvariants = [\"wet\"]\n";
  for (const auto& [extra, key] :
       std::vector<std::pair<std::string, std::string>>{{"cycles = 30\n", "cycles"},
                                                        {"gammas = [4.0, 3.0]\n", "gammas"},
                                                        {"cells = 2\n", "cells"},
                                                        {"columns = -1\n", "columns"},
                                                        {"gammas = [0.0]\n", "gammas"},
                                                        {"widths = [60.5]\n", "widths"},
                                                        {"seeds = [1, 1]\n", "seeds"},
                                                        {"boundaries = [\"open\"]\n", "boundaries"},
                                                        {"boundaries = []\n", "boundaries"}}) {
    granwave::StudyFile f = file(wet + extra);
    const std::string message = studyError([&] { granwave::SurfaceWavesStudy study(f); });
    EXPECT_TRUE(contains(message, "[continuum] " + key)) << message;
  }
  granwave::StudyFile f = file("[continuum]\nvariants = [\"moist\"]\n");
  const std::string message = studyError([&] { granwave::SurfaceWavesStudy study(f); });
  EXPECT_TRUE(contains(message, "[continuum] variants")) << message;
  EXPECT_TRUE(contains(message, "moist")) << message;
  // A [continuum] section without variants would silently run no continuum.
  granwave::StudyFile g = file("[continuum]\ngammas = [3.0]\n");
  const std::string none = studyError([&] { granwave::SurfaceWavesStudy study(g); });
  EXPECT_TRUE(contains(none, "[continuum] variants")) << none;
}
