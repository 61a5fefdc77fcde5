#pragma once
// The numbers of the effective-restitution study, per law: the theory curve e_eff(T), the
// collision statistics of the driven runs and the layer's temperature, free-cooling fits
// (smooth and with the scene's friction) per temperature range, and the constant-e hydro fit
// to the particle fields; written under /results/effective_restitution (docs/studies.md).
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/effective_restitution/CoolingFit.hpp"
#include "studies/effective_restitution/EffectiveRestitutionStudy.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

// One free-cooling run: the fit over the whole range and per temperature range.
struct CoolingRun {
  double nu = 0;
  bool rough = false;  // with the scene's friction (else mu = 0)
  double mu = 0;
  std::string failure;  // empty: the run finished
  CoolingFit all;
  std::vector<CoolingFit> ranges;   // the valid fits, highest temperature first
  std::vector<double> temperature;  // T / T0 of each range (the geometric mean of its samples)
  std::vector<double> theory;       // e_eff of the law at each range's temperature
  std::vector<double> tc_share;     // share of TC-elastic pair collisions in each range
};

// The constant-e hydro runs' chi^2 against the particles' area fraction, and the fit.
struct HydroFit {
  std::vector<double> e, chi2;
  Measurement best;
  double chi2_per_dof = NAN;
};

struct LawRestitution {
  std::vector<double> theory_temperature, theory_e;  // T / T0 and e_eff(T)
  Measurement collision_statistics;
  double layer_temperature = NAN, layer_low = NAN, layer_high = NAN;  // T / T0
  double theory_at_layer = NAN, theory_at_low = NAN, theory_at_high = NAN;
  std::vector<CoolingRun> cooling;  // smooth runs over nu, then the rough ones
  Measurement free_cooling, free_cooling_with_friction;
  HydroFit hydro;
  double largest_disagreement = NAN;  // sigma, over the pairs of the three estimates
  int compared = 0;                   // pairs that could be compared
};

struct EffectiveRestitutionResults {
  LawRestitution law[2];
};

EffectiveRestitutionResults analyseEffectiveRestitution(const EffectiveRestitutionConfig& config,
                                                        const RunSet& runs);
void writeEffectiveRestitutionResults(h5::File& file, const EffectiveRestitutionResults& results);

}  // namespace granwave
