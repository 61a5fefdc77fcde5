#include "studies/study_run/FollowUpProgress.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace granwave {

namespace {

bool alike(const RunRequest& a, const RunRequest& b) {
  return a.kind == b.kind && a.scene.particles.count == b.scene.particles.count &&
         a.scene.run.duration == b.scene.run.duration;
}

// "40 s", "3.2 min", "1.5 h".
std::string duration(double seconds) {
  if (seconds < 120) return fmt::format("{:.0f} s", seconds);
  if (seconds < 7200) return fmt::format("{:.1f} min", seconds / 60);
  return fmt::format("{:.1f} h", seconds / 3600);
}

}  // namespace

double expectedWall(const RunRequest& request, const RunSet& done) {
  for (const bool same_size : {true, false}) {
    double sum = 0;
    int n = 0;
    for (const RunRecord& r : done.all()) {
      if (!r.ok || r.wall <= 0) continue;
      if (same_size ? alike(r.request, request) : r.request.kind == request.kind) {
        sum += r.wall;
        ++n;
      }
    }
    if (n > 0) return sum / n;
  }
  return 0;
}

std::string followUpLine(int round, const FollowUp& more, const RunSet& done, int jobs) {
  std::string line = fmt::format("follow-up round {}: {} more run{}, because {}", round,
                                 more.runs.size(), more.runs.size() == 1 ? "" : "s", more.reason);
  line += more.rounds_after > 0
              ? fmt::format("; at most {} more round{} ({} runs) may follow", more.rounds_after,
                            more.rounds_after == 1 ? "" : "s", more.runs_after)
              : "; no further round can follow";
  double round_wall = 0;
  bool known = true;
  for (const RunRequest& q : more.runs) {
    const double w = expectedWall(q, done);
    known = known && w > 0;
    round_wall += w;
  }
  if (!known || more.runs.empty()) return line + " (no estimate of time: no such run finished yet)";
  const double per_run = round_wall / static_cast<double>(more.runs.size());
  const double at_a_time = std::max(1, jobs);
  const double later = per_run * static_cast<double>(more.runs_after) / at_a_time;
  line += fmt::format("; this round about {}", duration(round_wall / at_a_time));
  if (more.rounds_after > 0)
    line += fmt::format(", all that may follow at most about {}", duration(later));
  return line + fmt::format(" ({} at a time, at the pace of this study's runs so far)", jobs);
}

}  // namespace granwave
