#pragma once
// Period of a driven layer from its centre-of-mass height h(t), sampled M times per drive
// cycle (docs/classification.md, "Period").
//
// Over K whole cycles the spectrum of h has the drive's harmonics at bins K, 2K, ... and a
// period-p motion adds the subharmonics j K / p (j not a multiple of p). K is trimmed to a
// multiple of 12 so the subharmonics of periods 2, 3 and 4 fall on exact bins. The strength
// of period p is the amplitude ratio sqrt(P_sub(p) / P_harm), P_sub(p) the power at the
// subharmonics of p that are not subharmonics of a smaller period. The layer's period is
// the least common multiple of every p in {2, ..., max_period} whose ratio exceeds
// `threshold` (1 if none does).
#include <vector>

namespace granwave {

struct PeriodOptions {
  int samples_per_cycle = 100;  // M
  double threshold = 0.1;       // subharmonic / harmonic amplitude ratio for period p
  int max_period = 4;
};

struct PeriodResult {
  int period = 1;                 // in drive cycles
  int cycles_used = 0;            // K
  std::vector<double> strength;   // strength[p] for p = 0..max_period (0, 1 unused)
  double harmonic_amplitude = 0;  // m, amplitude of the drive-frequency component
};

// `height` holds M samples per cycle starting at a cycle boundary; the first
// `discard_cycles` cycles are skipped (transient). Throws std::invalid_argument if fewer
// than 12 cycles remain.
PeriodResult detectPeriod(const std::vector<double>& height, int discard_cycles,
                          const PeriodOptions& options = {});

// The period of a whole run: the one rule every command uses (simulate's summary, simulate
// --fields, fields, and through their files the studies), so a run has one period. Two rules
// disagree on a bistable layer: leaving out a fifth of the run or only the steady-state
// detector's transient, the two windows can give 2T and 1T for the same run. The transient left
// out is therefore the larger of the two (at least 3 cycles).
struct RunPeriod {
  PeriodResult result;
  int discarded = 0;  // leading cycles left out
};

// `com_height`: M samples per cycle from a cycle boundary. Throws std::invalid_argument if
// fewer than 12 cycles remain after the transient.
RunPeriod runPeriod(const std::vector<double>& com_height, int samples_per_cycle);

}  // namespace granwave
