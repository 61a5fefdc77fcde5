#include "studies/method_comparison/RunOutcomes.hpp"

#include <cmath>

namespace granwave {

double meanPhase(const std::vector<double>& v) {
  double c = 0, s = 0;
  for (double x : v) {
    c += std::cos(2 * M_PI * x);
    s += std::sin(2 * M_PI * x);
  }
  if (v.empty()) return NAN;
  // In (0.5, 1.5]: collision times near the end of a cycle read as 0.98, 1.01, not 0.01.
  double m = std::atan2(s, c) / (2 * M_PI);
  return m <= 0.5 ? m + 1 : m;
}

std::optional<FieldsRecord> particleFields(const RunSet& runs, const std::string& label) {
  const RunRecord& r = runs.get(label);
  if (!r.ok) return std::nullopt;
  return readFieldsFile(r.fieldsPath());
}

HydroOutcome hydroOutcome(const RunSet& runs, const std::string& label) {
  HydroOutcome h;
  const RunRecord& r = runs.get(label);
  h.cpu = r.cpu;
  if (!r.ok) {
    h.failure = r.message;
    return h;
  }
  h.fields = readHydroRunFile(r.hydroPath());
  h.fronts = impactFronts(h.fields->lab);
  h.collision_phase = meanPhase(centerOfMassMinimumPhases(h.fields->lab, h.fields->windowCycles()));
  return h;
}

VelocityFronts trackedHydroFronts(const HydroOutcome& h, double frequency) {
  if (!h.fields || h.fields->lab.phases() <= 1) return {};
  const PhaseProfiles& lab = h.fields->lab;
  return velocityFronts(lab, (lab.phase[1] - lab.phase[0]) / frequency);
}

}  // namespace granwave
