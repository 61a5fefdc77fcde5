#pragma once
// The readings study's report: the readings and what each costs physically, the table
// reading x statement with the measured numbers, the verdict map, and which reading (if any)
// reproduces the paper. No file I/O.
#include "studies/readings/ReadingsAnalysis.hpp"

namespace granwave {

void reportReadings(const ReadingsConfig& config, const ReadingsResults& results, Report& report);

}  // namespace granwave
