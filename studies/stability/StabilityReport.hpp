#pragma once
// The stability study's report: the two diagrams and where they differ, every point of the
// grid, the paper's features point by point, and the snapshot gallery. Figures, tables and
// prose only.
#include "studies/report/Report.hpp"
#include "studies/stability/StabilityAnalysis.hpp"

namespace granwave {

void reportStability(const StabilityConfig& config, const StabilityResults& results,
                     Report& report);

}  // namespace granwave
