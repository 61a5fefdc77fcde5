#pragma once
// The keys of the wave-fronts study's methods comparison (docs/studies.md): the paper's scene as
// the comparison judges it (scenes, seeds, the constant e standing in for each law), the
// verdict's tolerances and seeds, and the runs of cost against accuracy, of the failure map and
// of LAMMPS; with the labels of those runs. The study's own keys extend these
// (studies/wave_fronts/WaveFrontsStudy.hpp).
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

struct MethodComparisonConfig {
  LawScenes scenes;
  double e_eff[2] = {0, 0};  // constant restitution standing in for each law at T0
  double duration = 30;
  std::vector<int> seeds{1, 2, 3};
  // Verdict stability: seeds are added seed_step at a time (the next integers after the
  // largest listed) while the simplest-model verdict of a law is undecided, up to max_seeds;
  // `resamples` bootstrap resamples of the seeds give the verdict's agreement.
  int max_seeds = 21, seed_step = 2, resamples = 200;
  // A candidate reproduces the particles when the 95 % intervals of its front speed's
  // difference (relative to the reference's speed) and of its time share's difference lie
  // within these (docs/studies.md: the paper quotes its fronts to +-0.25 m/s, 13-16 %).
  double front_tolerance = 0.15, share_tolerance = 0.2;
  std::vector<int> extraSeeds() const;
  int window = 2, blocks = 5;
  // Phases per cycle of the hydro runs of the paper's scene (a dense layer's front crosses the
  // layer in a few ms); also the N sweep's.
  int sweep_phases = 400;
  std::vector<double> cost_durations{7.5, 15, 30, 60};
  std::vector<int> cost_cells{25, 50, 100, 200, 400};
  std::vector<double> cost_rtol{1e-3, 1e-4, 1e-5};
  std::vector<double> fail_gammas{1.5, 2.5, 4, 6, 8};
  double fail_duration = 5;
  std::vector<int> fail_cells{100, 400};
  std::vector<double> fail_rtol{1e-2, 1e-4};
  // The soft-sphere DEM alternative (LAMMPS; about 70 s per 15 s run here): "auto" runs it
  // when Debian's lammps is installed, "yes" requires it (installing it with install = true),
  // "no" leaves it out.
  std::string lammps_mode = "auto";
  bool lammps = false, lammps_install = false;
  std::string lammps_executable = "lmp", lammps_deck;
  double lammps_duration = 15;
  int lammps_seed = 1;

  // Run labels: "ED dry seed 1", "hydro wet Gamma=2.5 100 cells rtol 0.01", ...
  static std::string particleRun(int law, const std::string& tag) {
    return particleLabel(law, tag);
  }
  static std::string hydroRun(int law, const std::string& tag) { return hydroLabel(law, tag); }
  static std::string failureHydroRun(int law, double gamma, int cells, double rtol);
  static std::string costHydroRun(int cells, double rtol);
  std::string lammpsRun() const;
};

// The seeds of the paper's scene that ran: the study's, then any added for an undecided
// verdict.
std::vector<int> seedsOf(const MethodComparisonConfig& config, const RunSet& runs, int law);

}  // namespace granwave
