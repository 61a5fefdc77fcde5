#pragma once
// The share of a bistable layer's time spent in its period-2 state, pooled over seeds, and
// whether two such shares agree (docs/studies.md, "The simplest model that reproduces the
// particles"). A share is counted in 12-cycle windows (coarse_grain/PeriodDoublingSeries.hpp);
// neighbouring windows are correlated, so its binomial interval uses the effective number of
// windows, summed over seeds (independent runs).

#include <cmath>

namespace granwave {

struct StateShare {
  double share = NAN;            // windows in the period-2 state / windows (NaN: none)
  double low = NAN, high = NAN;  // 95 % Wilson interval over the effective windows
  double effective_windows = 0;  // 0 for an exact share (a deterministic model)
  bool known() const { return !std::isnan(share); }
};

// Pooled over seeds: windows and period-2 windows counted, effective windows summed.
StateShare pooledStateShare(int windows, int period2_windows, double effective_windows);
// A deterministic model's share, known exactly: 0 for period 1, 1 for period 2; unknown for
// any other period (0 = not periodic, 4, ...), whose f/2 content the state windows do not
// classify.
StateShare exactStateShare(int period);

// The 95 % interval of a - b by Newcombe's hybrid score method (method 10 of R. G. Newcombe,
// Statistics in Medicine 17, 873 (1998)), built from the two Wilson intervals; an exact share
// contributes no width.
struct ShareDifference {
  double difference = NAN, low = NAN, high = NAN;
  bool compatible() const { return low <= 0 && 0 <= high; }  // false if either is unknown
};
ShareDifference shareDifference(const StateShare& a, const StateShare& b);

}  // namespace granwave
