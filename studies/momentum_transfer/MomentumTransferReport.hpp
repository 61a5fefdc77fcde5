#pragma once
// The momentum-transfer study's report: the runs, the profiles of Fig. 7, the map and row
// mean of r_x (Fig. 8) with the tables, and what the runs give. Figures, tables and prose only.
#include "studies/momentum_transfer/MomentumTransferAnalysis.hpp"
#include "studies/report/Report.hpp"

namespace granwave {

void reportMomentumTransfer(const MomentumTransferConfig& config,
                            const MomentumTransferResults& results, Report& report);

}  // namespace granwave
