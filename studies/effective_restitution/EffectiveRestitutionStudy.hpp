#pragma once
// The effective-restitution study (docs/studies.md): one constant e_eff fitted to particle
// data three ways (free cooling, collision statistics of the driven run, constant-e hydro
// fitted to the particle fields), against the Maxwell-averaged theory e_eff(T). This file: the
// study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

struct EffectiveRestitutionConfig {
  LawScenes scenes;
  double duration = 30;
  std::vector<int> seeds{1, 2, 3};
  int window = 2, blocks = 5;
  std::vector<double> cooling_nu{0.2, 0.4, 0.6};
  int cooling_count = 1000;
  double cooling_t_start = 1.0;  // initial T / T0
  double cooling_t_end = 0.02;   // lowest T / T0 fitted
  double cooling_duration = 1.0, cooling_record = 0.001;
  int cooling_bins = 6;
  std::vector<double> hydro_e{0.5, 0.6, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95};

  static std::string coolingLabel(int law, double nu, bool rough);
  static std::string drivenLabel(int law, int seed);
  static std::string hydroLabel(double e);
};

class EffectiveRestitutionStudy final : public Study {
 public:
  explicit EffectiveRestitutionStudy(StudyFile& f);
  std::string title() const override {
    return "Effective restitution: can one constant stand for the velocity-dependent laws?";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  void readKeys(StudyFile& f);
  void addCoolingRuns(const StudyFile& f, int law);
  EffectiveRestitutionConfig c_;
  std::vector<RunRequest> requests_;
};

std::unique_ptr<Study> makeEffectiveRestitutionStudy(StudyFile& file);

}  // namespace granwave
