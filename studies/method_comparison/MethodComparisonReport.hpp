#pragma once
// The wave-fronts study's report on the methods themselves (docs/studies.md), section by
// section: cost against accuracy, where each method fails, the simplest model that reproduces
// the particles, soft-sphere DEM (LAMMPS). Figures, tables and prose only.
#include <optional>
#include <string>
#include <vector>

#include "studies/method_comparison/MethodComparison.hpp"
#include "studies/report/Report.hpp"

namespace granwave {

void costSection(const MethodComparisonConfig& config, const CostAccuracy& cost, Report& report);
void failureSection(const MethodComparisonConfig& config, const FailureMap& failures,
                    Report& report);
// Returns the verdicts of both laws, one line each (with what decided them and how often
// resamples of the seeds repeat them), for the study's headline.
std::vector<std::string> modelSection(const MethodComparisonConfig& config,
                                      const ModelHierarchy (&models)[2], Report& report);
// `dry_seed1` and `dry_hydro`: the dry layer's particle run of the first seed and its hydro run
// with the velocity-dependent closure, drawn beside LAMMPS.
void lammpsSection(const MethodComparisonConfig& config, const LammpsComparison& lammps,
                   const std::optional<FieldsRecord>& dry_seed1, const HydroOutcome& dry_hydro,
                   Report& report);

}  // namespace granwave
