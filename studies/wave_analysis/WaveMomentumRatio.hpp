#pragma once
// The paper's momentum-transfer ratio over the wet layer's internal wave (Sec. V, Figs. 7-8)
// for one dry and one wet run of the same drive: r_x(z, t) = RMS(v_x)_dry / RMS(v_x)_wet at
// the same plate phase, its row mean r~_x(t), averaged over the phases from the onset of the
// wet layer's strong impact front for `wave_duration` cycles. Rows where either layer is more
// dilute than min_area_fraction, or the wet RMS is below min_rms, are left out. The paper
// gives 2.17 +- 0.56 (mean and spread of r~_x over the wave).
#include "coarse_grain/FieldsReader.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

struct WaveRatioOptions {
  double wave_duration = 0.15;   // T
  double fallback_onset = 0.88;  // t/T used when the wet run has no impact front
  double min_rms = 1e-3;         // m/s
  double min_area_fraction = 0.1;
};

// value: mean of r~_x over the wave phases; error: its spread (standard deviation) over them.
// NaN when the fields do not match (phases, rows) or no row qualifies.
Measurement waveMomentumRatio(const FieldsRecord& dry, const FieldsRecord& wet,
                              const WaveRatioOptions& options);

}  // namespace granwave
