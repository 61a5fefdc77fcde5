#pragma once
// The stability study (docs/studies.md; the paper's Fig. 3): dry and wet layers over drive
// frequency f and acceleration Gamma, each scene run past its transient and classified live
// (period, surface waves, kinks, crystal / amorphous / liquid-like), drawn as two diagrams
// with the dry-wet differences marked, beside the hydro solver's period and failures on the
// same grid, a snapshot gallery, and the paper's qualitative features checked one by one.
// This file: the study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

struct StabilityConfig {
  LawScenes scenes;
  std::vector<double> frequencies{10, 15, 20, 30};
  std::vector<double> gammas{2, 3, 4, 5, 6, 7};
  double cycles = 150;
  std::vector<int> seeds{1, 2, 3};
  // Seeds added, seed_step at a time, at the points whose seeds disagree while a feature's
  // verdict is undecided, up to max_seeds at a point (docs/studies.md, "Stability over seeds").
  int max_seeds = 5, seed_step = 2;
  int window = 2, blocks = 5;
  bool hydro = true;
  bool hydro_rough = true;  // also the rough-particle closure (rotational temperature)
  int gallery_per_state = 2;

  // The seeds after `seeds`, up to max_seeds in all: the next integers after the largest.
  std::vector<int> extraSeeds() const;
  static std::string particleRun(int law, double f, double gamma, int seed);
  static std::string hydroRun(int law, double f, double gamma, bool rough = false);
};

class StabilityStudy final : public Study {
 public:
  explicit StabilityStudy(StudyFile& f);
  std::string title() const override {
    return "Stability diagrams of dry and wet vibrated layers (the paper's Fig. 3)";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  FollowUp followUp(const RunSet& runs) const override;
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  void readKeys(StudyFile& f);
  // The continuum at one point (one run: it has no seed), smooth disks or rough particles.
  void addHydro(StudyFile& f, int law, double fr, double gamma, std::vector<std::string> o,
                bool rough);
  RunRequest particleRequest(StudyFile& f, int law, double fr, double gamma, int seed) const;
  StabilityConfig c_;
  std::vector<RunRequest> requests_;
  // [point] -> the runs of the extra seeds there, seed by seed (dry, wet), for followUp;
  // points in the grid's order (f, then Gamma).
  std::vector<std::vector<RunRequest>> extra_;
};

std::unique_ptr<Study> makeStabilityStudy(StudyFile& file);

}  // namespace granwave
