#pragma once
// The wave-fronts study (docs/studies.md): the paper's wave-propagation section (Sec. IV,
// Figs. 4, 5, 6) from the particles and from the hydro solver, the cost of each against its
// accuracy, where each method fails, the simplest model that reproduces the particles, and
// soft-sphere DEM (LAMMPS) beside them. This file: the study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/framework/Study.hpp"
#include "studies/framework/StudyScenes.hpp"

namespace granwave {

struct WaveFrontsConfig {
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
  std::vector<double> profile_phases{0.88, 0.90, 0.92, 0.94, 0.96};
  double sweep_duration = 20;
  // Cycles the particles average for one answer (period and front), for the cost per answer.
  double answer_cycles = 150;
  std::vector<int> counts{150, 300, 450, 600};
  // The N sweep's seeds (the first also gives the T~_g fronts and the cost), its phases per
  // cycle (a dense layer's front crosses it in a few ms), and the free height kept above the
  // close-packed layer: the lid is raised for counts whose layer would leave less.
  std::vector<int> sweep_seeds{1, 2};
  int sweep_phases = 400;
  double sweep_headroom = 0.02;  // m
  // Scene overrides of one count's runs (particles.count, and container.height if raised).
  std::vector<std::string> countOverrides(int law, int count) const;
  static std::string countTag(int count, int seed, int first_seed);
  std::vector<double> stokes{20, 40, 80}, e_inf{0.8, 0.91, 0.95};
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
  // Drive cycles of one sweep run of `law` (its duration at the scene's frequency).
  double sweepCycles(int law) const { return sweep_duration * scenes.base[law].drive.frequency; }
  std::string lammpsRun() const;
};

class WaveFrontsStudy final : public Study {
 public:
  explicit WaveFrontsStudy(StudyFile& f);
  std::string title() const override {
    return "Wave fronts in vibrated dry and wet layers: particles against the continuum";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  FollowUp followUp(const RunSet& runs) const override;
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  void readKeys(StudyFile& f);
  void planLaw(const StudyFile& f, int law);
  // The runs of one seed of the paper's scene: the full model and the simpler particle models.
  void planSeed(const StudyFile& f, int law, int seed, std::vector<RunRequest>& into);
  void planWetSweeps(const StudyFile& f);
  void addLammps(StudyFile& f);
  // A run of `law` with the study's overrides and `overrides`; particle runs last `duration`.
  RunRequest& add(const StudyFile& f, RunKind kind, int law, const std::string& label,
                  std::vector<std::string> overrides, double duration);

  WaveFrontsConfig c_;
  std::vector<RunRequest> requests_;
  std::vector<RunRequest> extra_[2];  // [law]: the added seeds' runs, seed by seed
};

std::unique_ptr<Study> makeWaveFrontsStudy(StudyFile& file);

}  // namespace granwave
