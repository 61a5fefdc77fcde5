#pragma once
// The state of a bistable layer as a time series (docs/classification.md, "Layer state over
// time").
//
// The wet layer at f = 10 Hz, Gamma = 4 switches between a period-1 and a period-2 state, so
// the period of a whole run is partly chance. Here the steady part of the centre-of-mass
// height is cut into consecutive windows of `window_cycles` cycles (12: the subharmonics of
// periods 2, 3, 4 fall on exact bins, PeriodDetector.hpp), starting at the first even cycle
// after the transient (so a window's cycle parity is the absolute one, as in the phase
// averager). A window's f/2 strength is detectPeriod's strength[2]: sqrt(P_f2 / P_harm).
//
// Threshold from the window's own noise: the same comb of bins shifted by a few bins off the
// f/2 lines (shifts that land on no harmonic and no subharmonic of periods 2-4; for 12-cycle
// windows +-1, +-4, +-5 bins) carries only the layer's broadband fluctuations. Its mean power,
// over the six shifted combs, estimates what the f/2 comb would hold without a subharmonic:
// the noise strength s_n = sqrt(mean comb power / P_harm). The window is in the period-2 state
// when its strength exceeds max(0.1, 3 s_n): 3 s_n is 9 times the expected noise power, which
// a comb dominated by one exponential (chi-square, 2 degrees of freedom) bin exceeds with
// probability e^-9 ~ 1e-4 per window; the floor 0.1 is the whole-run detector's threshold, so
// a window's state and the run's period use the same strength scale.
//
// Episodes: maximal runs of consecutive windows in one state, so their boundaries are exact up
// to one window.
//
// The share of time in the period-2 state and its uncertainty: consecutive windows are
// correlated (a state lasts longer than a window), so the binomial count uses the effective
// number of windows n_eff = n / tau, with tau = 1 + 2 sum_k rho_k the integrated
// autocorrelation time of the 0/1 series, summed while rho_k > 0 (Geyer's initial positive
// sequence; Geyer, Stat. Sci. 7, 473 (1992)); a series that never switches gives no estimate of
// tau, and n_eff = 1 is taken (one observation of one state). The interval is Wilson's 95 %
// score interval with n_eff (Wilson, JASA 22, 209 (1927)).
#include <algorithm>
#include <complex>
#include <vector>

namespace granwave {

// One window of the series.
struct F2Window {
  double strength = 0;        // sqrt(P_f2 / P_harm)
  double noise_strength = 0;  // s_n, from the shifted combs
  double threshold = 0;       // max(floor, 3 s_n)
  std::complex<double> f2;    // Fourier coefficient at f/2 (first f/2 bin), from the window start
  bool period2 = false;
};

// `window`: window_cycles * M samples from a cycle boundary. Throws std::invalid_argument if
// the window is not a positive multiple of 12 cycles or M < 4.
F2Window f2Window(const double* window, int window_cycles, int samples_per_cycle,
                  double floor = 0.1);

struct StateEpisode {
  int first_cycle = 0, cycles = 0;
  int period = 1;  // 1 or 2
};

struct PeriodDoublingSeries {
  int window_cycles = 12;
  int first_cycle = 0;                   // first cycle of the first window (even)
  std::vector<double> f2_strength;       // per window, in order
  std::vector<double> noise_strength;    // s_n per window
  std::vector<double> threshold;         // per window
  std::vector<int> period2;              // 1 if the window is in the period-2 state
  std::vector<StateEpisode> episodes;    // in order, covering every window
  double period2_share = 0;              // share of windows in the period-2 state
  double share_low = 0, share_high = 1;  // 95 % Wilson interval with n_eff
  double effective_windows = 0;          // n_eff
  int switches = 0;                      // state changes between consecutive windows
};

// Windows in the period-2 state.
inline int period2Windows(const PeriodDoublingSeries& s) {
  return static_cast<int>(std::count(s.period2.begin(), s.period2.end(), 1));
}

// `com_height`: M samples per cycle from a cycle boundary; the first `discard_cycles` cycles
// (rounded up to even) are left out and the windows follow on, an incomplete last window left
// out. Throws std::invalid_argument if no whole window remains or `window_cycles` is not a
// positive multiple of 12.
PeriodDoublingSeries periodDoublingSeries(const std::vector<double>& com_height,
                                          int samples_per_cycle, int discard_cycles,
                                          int window_cycles = 12, double floor = 0.1);

// The standard normal deviate of a two-sided 95 % interval.
constexpr double kZ95 = 1.959963984540054;
// Wilson's 95 % score interval for a share p of n (n > 0, not necessarily whole) trials.
void wilsonInterval(double p, double n, double& low, double& high);

}  // namespace granwave
