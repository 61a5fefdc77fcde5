#pragma once
// The state of a bistable layer as a time series (docs/classification.md, "Period").
//
// The wet layer at f = 10 Hz, Gamma = 4 switches between a period-1 and a period-2 state, so
// the period of a whole run is partly chance. Here the steady part of the centre-of-mass
// height is cut into consecutive windows of `window_cycles` cycles (12: the subharmonics of
// periods 2, 3, 4 fall on exact bins, PeriodDetector.hpp); each window's f/2 strength is
// detectPeriod's strength[2], and the window is in the period-2 state when it exceeds the
// same threshold (0.1). The share of windows in that state estimates the fraction of time.
//
// Its uncertainty: consecutive windows are correlated (a state lasts longer than a window),
// so the binomial count uses the effective number of windows n_eff = n / tau, with
// tau = 1 + 2 sum_k rho_k the integrated autocorrelation time of the 0/1 series, summed while
// rho_k > 0 (Geyer's initial positive sequence; Geyer, Stat. Sci. 7, 473 (1992)); a series
// that never switches gives no estimate of tau, and n_eff = 1 is taken (one observation of
// one state). The interval is Wilson's 95 % score interval with n_eff (Wilson, JASA 22, 209
// (1927)), which stays inside [0, 1] and is not empty at a share of 0 or 1.
#include <vector>

namespace granwave {

struct PeriodDoublingSeries {
  int window_cycles = 12;
  int first_cycle = 0;                   // first cycle of the first window
  std::vector<double> f2_strength;       // per window, in order
  std::vector<int> period2;              // 1 if the window is in the period-2 state
  double period2_share = 0;              // share of windows in the period-2 state
  double share_low = 0, share_high = 1;  // 95 % Wilson interval with n_eff
  double effective_windows = 0;          // n_eff
  int switches = 0;                      // state changes between consecutive windows
};

// `com_height`: M samples per cycle from a cycle boundary; the first `discard_cycles` cycles
// are left out, and windows are aligned to the end of the series (as detectPeriod). Throws
// std::invalid_argument if no whole window remains or `window_cycles` is not a positive
// multiple of 12.
PeriodDoublingSeries periodDoublingSeries(const std::vector<double>& com_height,
                                          int samples_per_cycle, int discard_cycles,
                                          int window_cycles = 12, double threshold = 0.1);

// Wilson's 95 % score interval for a share p of n (n > 0, not necessarily whole) trials.
void wilsonInterval(double p, double n, double& low, double& high);

}  // namespace granwave
