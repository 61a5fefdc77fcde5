#pragma once
// When has a driven layer forgotten its initial state? From the centre-of-mass height per
// cycle (mean over the cycle): the layer is steady from the first cycle c >= min_cycles
// after which two consecutive windows of `window` cycles have means that agree within
// `sigmas` standard errors (the standard error from the cycle-to-cycle scatter in those
// windows), or within `floor` (relative, for an almost noise-free layer). Works online: feed
// one cycle at a time.
#include <vector>

namespace granwave {

struct SteadyStateOptions {
  int window = 6;      // cycles per window (even, and a multiple of 3: periods 1-3 average out)
  int min_cycles = 5;  // never fewer discarded
  double sigmas = 3.0;
  double floor = 1e-3;  // relative tolerance when the scatter is tiny
};

class SteadyStateDetector {
 public:
  explicit SteadyStateDetector(const SteadyStateOptions& o = {}) : opt_(o) {}
  // Adds the next cycle's mean height; returns true once steady (and from then on).
  bool addCycle(double mean_height);
  bool steady() const { return steady_from_ >= 0; }
  // First steady cycle (the number of discarded cycles), or -1.
  int steadyFrom() const { return steady_from_; }
  int cycles() const { return static_cast<int>(h_.size()); }
  // The cycle means added so far; feeding them to a fresh detector restores this one.
  const std::vector<double>& history() const { return h_; }

 private:
  SteadyStateOptions opt_;
  std::vector<double> h_;
  int steady_from_ = -1;
};

// Offline: the number of leading cycles to discard for a centre-of-mass series sampled M
// times per cycle (-1 if it never becomes steady).
int steadyCycles(const std::vector<double>& com_height, int samples_per_cycle,
                 const SteadyStateOptions& o = {});

}  // namespace granwave
