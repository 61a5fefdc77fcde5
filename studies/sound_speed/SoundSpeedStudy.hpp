#pragma once
// The sound-speed study (docs/studies.md): does constant-restitution sound-speed and shock
// theory hold for the fronts the particles show? Each impact front of dry and wet runs over
// N and Gamma is compared with the adiabatic and isothermal sound speeds of the gas ahead,
// the Rankine-Hugoniot and strong-shock speeds, the compaction-front limit, and mass
// conservation across the measured states. This file: the study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

struct SoundSpeedConfig {
  LawScenes scenes;
  double duration = 20;
  int seed = 1, window = 2, blocks = 5;
  std::vector<int> counts{150, 300, 600};
  std::vector<double> gammas{3, 4, 5};
  int rows = 3, gap = 1;  // rows sampled on each side of the front, rows skipped before them

  static std::string label(int law, int n, double gamma);
};

class SoundSpeedStudy final : public Study {
 public:
  explicit SoundSpeedStudy(StudyFile& f);
  std::string title() const override {
    return "Sound speed and shocks: does constant-restitution theory describe the fronts?";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  SoundSpeedConfig c_;
  std::vector<RunRequest> requests_;
};

std::unique_ptr<Study> makeSoundSpeedStudy(StudyFile& file);

}  // namespace granwave
