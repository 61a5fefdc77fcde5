#pragma once
// The effective-restitution study's report: e_eff against temperature with the three fits and
// the theory, the table of the three estimates, the free-cooling fits by temperature range, and
// whether one constant describes each law. Figures, tables and prose only.
#include "studies/effective_restitution/EffectiveRestitutionAnalysis.hpp"
#include "studies/report/Report.hpp"

namespace granwave {

void reportEffectiveRestitution(const EffectiveRestitutionConfig& config,
                                const EffectiveRestitutionResults& results, Report& report);

}  // namespace granwave
