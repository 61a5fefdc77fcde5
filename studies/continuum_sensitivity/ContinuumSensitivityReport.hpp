#pragma once
// The report of the continuum-sensitivity study: per case, a table of each variant's answers
// and how far they moved from the base run's, and a headline of what held (no file I/O).
#include "studies/continuum_sensitivity/ContinuumSensitivityAnalysis.hpp"
#include "studies/report/Report.hpp"

namespace granwave {

void reportContinuumSensitivity(const ContinuumSensitivityConfig& config,
                                const ContinuumSensitivityResults& results, Report& report);

}  // namespace granwave
