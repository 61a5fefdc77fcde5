#include "studies/particle_run/VelocityFrontSummary.hpp"

#include <fmt/format.h>

#include "coarse_grain/FrontTransit.hpp"

namespace granwave {

namespace {

std::string transitText(const FrontTransit& t) {
  if (!t.reached) return "not reached";
  if (!t.resolved) return fmt::format("> {:.1f} m/s", t.speed_lower_bound);
  return fmt::format("{:.2f} m/s", t.speed);
}

}  // namespace

std::string velocityFrontLines(const PhaseProfiles& profiles) {
  if (profiles.time.size() < 2) return {};
  const double dt = profiles.time[1] - profiles.time[0];
  const FrontProfiles p = frontProfiles(profiles.pooled, profiles.z);
  const FrontTrackOptions o;
  const double* q = kReportedFractions;
  std::string r;
  for (const TrackedFront& f : trackFronts(p, dt, o)) {
    if (f.points < o.min_points && f.bulk_crossing <= 0) continue;
    const std::string fit = f.resolved ? fmt::format("{:.2f} +- {:.2f} m/s", f.speed, f.fit_error)
                                       : fmt::format("> {:.1f} m/s", f.speed_lower_bound);
    r += fmt::format(
        "velocity front  t/T {:.3f}: {} (fit, lab){}; transits {} (mass {:g}-{:g}), {} "
        "({:g}-{:g})\n",
        profiles.phase[static_cast<std::size_t>(f.first_phase)], fit,
        f.bulk_crossing > 0
            ? fmt::format(", after crossing {:.1f} mm within a phase", 1e3 * f.bulk_crossing)
            : std::string(),
        transitText(frontTransit(p, f, dt, q[0], q[1], o)), q[0], q[1],
        transitText(frontTransit(p, f, dt, q[1], q[2], o)), q[1], q[2]);
  }
  return r;
}

}  // namespace granwave
