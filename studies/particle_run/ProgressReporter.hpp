#pragma once
// Progress line on stderr for runs longer than a couple of seconds: an observer that looks
// at the wall clock at each record and prints at most every `interval` seconds.
#include <chrono>
#include <cstdio>

#include "particles/Snapshot.hpp"

namespace granwave {

class ProgressReporter : public SnapshotObserver {
 public:
  ProgressReporter(double duration, double interval_s = 2.0, std::FILE* out = stderr);
  void observe(const Snapshot& s) override;
  void finish();  // ends the progress line if one was printed

 private:
  using Clock = std::chrono::steady_clock;
  double duration_;
  double interval_;
  std::FILE* out_;
  Clock::time_point start_, last_;
  bool printed_ = false;
};

}  // namespace granwave
