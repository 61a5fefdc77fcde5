#pragma once
// The readings study (docs/studies.md): the paper's text leaves the units of kappa
// in e_dry = 1 - kappa v_n^(1/5), the meaning of its tangential "COR set to 1" (walls, TC
// collisions) and the TC window open. Each reading is a set of scene options enumerated from
// the text (never fitted); for each, dry and wet layers are run at the paper's checks with
// several seeds, and the report states which of the paper's statements the reading
// reproduces. This file: the study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

// One reading of the text: the values of the four contact keys it sets (docs/scenes.md).
struct Reading {
  std::string name, kappa_units, wall_tangential, tc_tangential, tc_window;
  double kappa_si = 0;  // (s/m)^(1/5), of the dry scene under this reading
  std::vector<std::string> overrides() const;
};

// A drive point of the checks.
struct DrivePoint {
  double frequency = 10, gamma = 4;
};

struct ReadingsConfig {
  LawScenes scenes;
  std::vector<Reading> readings;
  double frequency = 10;                         // Hz, the paper's lowest frequency
  std::vector<double> gammas{3, 4, 5};           // surface waves (dry) at f
  double wave_gamma = 4;                         // CM period and phase, fronts, r_x (Fig. 5-8)
  std::vector<double> high_frequencies{20, 30};  // re-crystallisation at Gamma ~ 5 as f rises
  double high_gamma = 5;
  double cycles = 150;  // run length; the paper: at least 15 s
  std::vector<int> seeds{1, 2, 3, 4, 5};
  int window = 2, blocks = 5;
  double wave_duration = 0.15;  // T, r_x averaged from the wet impact onset
  double min_rms = 1e-3, min_area_fraction = 0.1;
  double wave_v0 = 0;  // m/s, the plate's peak speed at (f, wave_gamma)

  std::vector<DrivePoint> points() const;  // gammas at f, then the high-frequency points
  int wavePoint() const;                   // index of (f, wave_gamma) in points()
  std::string run(int reading, int law, const DrivePoint& p, int seed) const;
};

class ReadingsStudy final : public Study {
 public:
  explicit ReadingsStudy(StudyFile& f);
  std::string title() const override {
    return "Readings of the paper's model text and the statements each reproduces";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  void readKeys(StudyFile& f);
  void readReadings(StudyFile& f);
  ReadingsConfig c_;
  std::vector<RunRequest> requests_;
};

std::unique_ptr<Study> makeReadingsStudy(StudyFile& file);

}  // namespace granwave
