#pragma once
// The momentum-transfer study (docs/studies.md): the paper's Sec. V (Figs. 7, 8) from dry and
// wet particle runs of the paper's scene. RMS(v_x) and v~_z profiles of both layers at the
// paper's phase, the deficiency factor r_x(z, t) = RMS(v_x)_dry / RMS(v_x)_wet during the wet
// layer's impact wave and its row mean r~_x(t), against the binary-collision value 2 and the
// paper's 2.17 +- 0.56. This file: the study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

struct MomentumTransferConfig {
  LawScenes scenes;
  double duration = 30;
  std::vector<int> seeds{1, 2, 3};
  int window = 2, blocks = 5;
  double profile_phase = 0.88;     // t/T of Fig. 7 (the paper's impact begins here)
  double wave_duration = 0.15;     // T: r~_x is averaged from the wet impact onset over this
  double margin = 0.05;            // T shown before and after the wave window in Fig. 8
  double min_rms = 1e-3;           // m/s: rows with a smaller wet RMS(v_x) are left out
  double min_area_fraction = 0.1;  // rows where either layer is more dilute are left out

  static std::string label(int law, int seed);
  // The same seed's run with the other phase window (1 cycle if `window` is 2 or more, else
  // 2): r_x with both windows (a 1-cycle window averages a period-2 layer's two impacts).
  int otherWindow() const { return window == 1 ? 2 : 1; }
  static std::string otherWindowLabel(int law, int seed, int window);
};

class MomentumTransferStudy final : public Study {
 public:
  explicit MomentumTransferStudy(StudyFile& f);
  std::string title() const override {
    return "Momentum transfer in vibrated dry and wet layers: the deficiency factor r_x";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  MomentumTransferConfig c_;
  std::vector<RunRequest> requests_;
};

std::unique_ptr<Study> makeMomentumTransferStudy(StudyFile& file);

}  // namespace granwave
