// Where each method fails (docs/studies.md): the particles without the TC model and the hydro
// solver over Gamma x grid x tolerance, each case run, its outcome read back.
#include <fmt/format.h>

#include "studies/contract/FailureReason.hpp"
#include "studies/contract/StudyResults.hpp"
#include "studies/method_comparison/MethodComparison.hpp"

namespace granwave {

namespace {

FailureCase particleFailure(const RunSet& runs, int law, double gamma) {
  FailureCase f;
  const RunRecord& r = runs.get(MethodComparisonConfig::particleRun(
      law, fmt::format("no TC Gamma={}", formatCompact(gamma))));
  f.ok = r.ok;
  if (r.ok) {
    f.period = readFieldsFile(r.fieldsPath()).context.layer_period;
  } else {
    f.failure = r.message;
    f.collapse_time = collapseTime(r.message);
  }
  return f;
}

FailureCase hydroFailure(const RunSet& runs, int law, double gamma, int cells, double rtol) {
  FailureCase f;
  const HydroOutcome h =
      hydroOutcome(runs, MethodComparisonConfig::failureHydroRun(law, gamma, cells, rtol));
  f.ok = h.fields.has_value();
  f.failure = h.failure;
  if (f.ok) {
    f.periodic = h.fields->periodic;
    f.period = static_cast<int>(h.fields->period);
    f.cycles = static_cast<int>(h.fields->cycles);
    f.regime = h.fields->regime;
  }
  return f;
}

}  // namespace

FailureMap analyseFailures(const MethodComparisonConfig& c, const RunSet& runs) {
  FailureMap out;
  for (int law = 0; law < kLaws; ++law)
    for (int cells : c.fail_cells)
      for (double rtol : c.fail_rtol)
        out.hydro_cases.push_back(
            fmt::format("{} {} cells rtol {:g}", kLawNames[law], cells, rtol));
  for (double gamma : c.fail_gammas) {
    std::vector<FailureCase> particles, hydro;
    for (int law = 0; law < kLaws; ++law) particles.push_back(particleFailure(runs, law, gamma));
    for (int law = 0; law < kLaws; ++law)
      for (int cells : c.fail_cells)
        for (double rtol : c.fail_rtol) {
          hydro.push_back(hydroFailure(runs, law, gamma, cells, rtol));
          out.hydro_failures += !hydro.back().ok;
        }
    out.particles.push_back(particles);
    out.hydro.push_back(hydro);
  }
  return out;
}

void writeFailures(h5::File& f, const std::string& root, const MethodComparisonConfig& c,
                   const FailureMap& m) {
  for (int law = 0; law < kLaws; ++law) {
    std::vector<double> collapse;
    for (const auto& row : m.particles) collapse.push_back(row[law].collapse_time);
    putSeries(f, fmt::format("{}/failure/ed_no_tc_collapse_time_{}", root, kLawNames[law]),
              collapse, "s");
  }
  putSeries(f, root + "/failure/gamma", c.fail_gammas, "1");
  putValue(f, root + "/failure", "hydro_failures", m.hydro_failures);
}

}  // namespace granwave
