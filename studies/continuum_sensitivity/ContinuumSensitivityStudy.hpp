#pragma once
// The continuum-sensitivity study (docs/studies.md, docs/hydro.md "Sensitivity to the
// numerical parameters"): do the continuum's answers (its period, its centre-of-mass
// trajectory, its impact front) stay put when a numerical or regularisation parameter is
// halved or doubled? A model's answer counts only if they do. This file: the study's keys and
// its runs, one hydro run per case and variant.
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "coarse_grain/FrontTransit.hpp"
#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

// A scene the study holds fixed while it varies the parameters: a law and its overrides.
struct SensitivityCase {
  std::string name;
  int law = 0;
  std::vector<std::string> set;
};

// One run of a case: the base (parameter empty) or one parameter scaled by a factor.
struct SensitivityVariant {
  std::string parameter;  // a [hydro] or [run] scene key, "" for the base
  double factor = 1;
  double value = 0;  // the key's value in this run
  std::string label;
};

struct ContinuumSensitivityConfig {
  LawScenes scenes;
  std::vector<SensitivityCase> cases;
  std::vector<std::string> parameters{"hydro.artificial_viscosity",
                                      "hydro.wall_contact_range",
                                      "hydro.wall_contact_stiffness",
                                      "hydro.packing_width",
                                      "hydro.temperature_floor",
                                      "hydro.cells",
                                      "hydro.rtol"};
  std::vector<double> factors{0.5, 2.0};
  double tolerance = 0.05;  // the largest relative change that counts as "does not move"
  int phases_per_cycle = 400;
  // Mass fractions of the layer between which the fronts' transit speeds are compared: the
  // lower and the upper half, less the tenth at each end where a front starts and fades.
  std::vector<double> front_fractions{std::begin(kReportedFractions), std::end(kReportedFractions)};
  std::vector<std::vector<SensitivityVariant>> variants;  // [case][variant], base first
};

class ContinuumSensitivityStudy final : public Study {
 public:
  explicit ContinuumSensitivityStudy(StudyFile& f);
  std::string title() const override {
    return "Continuum sensitivity: do the continuum's answers depend on its numerical "
           "parameters?";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  ContinuumSensitivityConfig c_;
  std::vector<RunRequest> requests_;
};

std::unique_ptr<Study> makeContinuumSensitivityStudy(StudyFile& file);

// The value of a numeric scene key the study may vary (StudyError naming the valid ones).
double sensitivityKeyValue(const Scene& scene, const std::string& key);
// The keys it may vary, for the study file's error message and the docs.
const std::vector<std::string>& sensitivityKeys();

}  // namespace granwave
