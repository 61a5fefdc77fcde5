#pragma once
// The stability study's tables of how its verdicts depend on the seeds: the paper's features
// with the share of seed resamples that keep each verdict, and the dry-wet difference counts
// per frequency over the resamples (docs/studies.md, "Stability over seeds").
#include "studies/report/Report.hpp"
#include "studies/stability/StabilityAnalysis.hpp"

namespace granwave {

Table featuresTable(const StabilityResults& results);
Table differencesTable(const StabilityResults& results);

}  // namespace granwave
