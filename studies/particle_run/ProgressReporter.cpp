#include "studies/particle_run/ProgressReporter.hpp"

#include <fmt/format.h>

namespace granwave {

ProgressReporter::ProgressReporter(double duration, double interval_s, std::FILE* out)
    : duration_(duration), interval_(interval_s), out_(out), start_(Clock::now()), last_(start_) {}

void ProgressReporter::observe(const Snapshot& s) {
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_) return;
  last_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double frac = duration_ > 0 ? s.time / duration_ : 1.0;
  const double eta = frac > 0 ? wall * (1.0 - frac) / frac : 0.0;
  fmt::print(out_, "\r  t = {:.3f} / {:.3f} s ({:3.0f}%)  {:.3g} events/s  ETA {:.0f} s   ", s.time,
             duration_, 100.0 * frac, s.obs.events / std::max(wall, 1e-9), eta);
  std::fflush(out_);
  printed_ = true;
}

void ProgressReporter::finish() {
  if (printed_) fmt::print(out_, "\n");
  printed_ = false;
}

}  // namespace granwave
