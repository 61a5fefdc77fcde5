#pragma once
// The wave-fronts study (docs/studies.md): the paper's wave-propagation section (Sec. IV,
// Figs. 4, 5, 6) from the particles and from the hydro solver (this folder), and the comparison
// of the methods on the same scene: the cost of each against its accuracy, where each fails,
// the simplest model that reproduces the particles, and soft-sphere DEM (LAMMPS) beside them
// (studies/method_comparison/). This file: the study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/method_comparison/MethodComparisonConfig.hpp"
#include "studies/method_comparison/MethodRuns.hpp"

namespace granwave {

// The study's keys: those of the methods comparison and the paper's fronts' own.
struct WaveFrontsConfig : MethodComparisonConfig {
  std::vector<double> profile_phases{0.88, 0.90, 0.92, 0.94, 0.96};
  double sweep_duration = 20;
  // Cycles the particles average for one answer (period and front), for the cost per answer.
  double answer_cycles = 150;
  std::vector<int> counts{150, 300, 450, 600};
  // The N sweep's seeds (the first also gives the T~_g fronts and the cost) and the free height
  // kept above the close-packed layer: the lid is raised for counts whose layer would leave
  // less.
  std::vector<int> sweep_seeds{1, 2};
  double sweep_headroom = 0.02;  // m
  // Scene overrides of one count's runs (particles.count, and container.height if raised).
  std::vector<std::string> countOverrides(int law, int count) const;
  static std::string countTag(int count, int seed, int first_seed);
  std::vector<double> stokes{20, 40, 80}, e_inf{0.8, 0.91, 0.95};
  // Drive cycles of one sweep run of `law` (its duration at the scene's frequency).
  double sweepCycles(int law) const { return sweep_duration * scenes.base[law].drive.frequency; }
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
  // A run of `law` with the study's overrides and `overrides`; particle runs last `duration`.
  RunRequest& add(const StudyFile& f, RunKind kind, int law, const std::string& label,
                  std::vector<std::string> overrides, double duration);
  RunRequest& add(const StudyFile& f, const PlannedRun& run);

  WaveFrontsConfig c_;
  std::vector<RunRequest> requests_;
  std::vector<RunRequest> extra_[2];  // [law]: the added seeds' runs, seed by seed
};

std::unique_ptr<Study> makeWaveFrontsStudy(StudyFile& file);

}  // namespace granwave
