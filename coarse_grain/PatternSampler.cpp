#include "coarse_grain/PatternSampler.hpp"

#include <cstdint>
#include <numeric>
#include <string>

#include "coarse_grain/SurfaceProfile.hpp"
#include "h5/H5Error.hpp"
#include "particles/StateArchive.hpp"

namespace granwave {

void PatternSampler::observe(const Snapshot& s) {
  const int M = cfg_.records_per_cycle;
  const int stride = std::max(1, M / cfg_.samples_per_cycle);
  const long cycle = static_cast<long>(s.step / static_cast<std::uint64_t>(M));
  const int phase = static_cast<int>(s.step % static_cast<std::uint64_t>(M));
  if (phase % stride != 0 || phase / stride >= cfg_.samples_per_cycle) return;
  if (cycle != current_) {
    current_ = cycle;
    cycles_.emplace_back();
    // One extra: the newest cycle may still be filling.
    while (static_cast<int>(cycles_.size()) > cfg_.keep_cycles + 1) cycles_.pop_front();
  }
  cycles_.back().push_back(s);
}

// All kept snapshots in one archive, with the number of snapshots of each cycle (the newest
// may be partial).
void PatternSampler::saveState(h5::File& file, const std::string& group) const {
  std::vector<Snapshot> all;
  std::vector<std::int64_t> sizes;
  for (const auto& c : cycles_) {
    all.insert(all.end(), c.begin(), c.end());
    sizes.push_back(static_cast<std::int64_t>(c.size()));
  }
  writeSnapshots(file, group + "/snapshots", all);
  file.writeDataset(group + "/cycle_sizes", sizes, {sizes.size()});
  file.writeAttribute<std::int64_t>(group, "current_cycle", current_);
}

void PatternSampler::restoreState(const h5::File& file, const std::string& group) {
  const std::vector<Snapshot> all = readSnapshots(file, group + "/snapshots");
  const auto sizes = file.readDataset<std::int64_t>(group + "/cycle_sizes");
  cycles_.clear();
  std::size_t next = 0;
  for (std::int64_t size : sizes) {
    if (size < 0 || next + static_cast<std::size_t>(size) > all.size())
      throw h5::H5Error(file.name() + ": " + group + "/cycle_sizes does not match its snapshots");
    cycles_.emplace_back(all.begin() + static_cast<std::ptrdiff_t>(next),
                         all.begin() + static_cast<std::ptrdiff_t>(next + size));
    next += static_cast<std::size_t>(size);
  }
  if (next != all.size())
    throw h5::H5Error(file.name() + ": " + group + "/cycle_sizes does not match its snapshots");
  current_ = static_cast<long>(file.readAttribute<std::int64_t>(group, "current_cycle"));
}

std::vector<std::vector<Snapshot>> PatternSampler::cycles() const {
  std::vector<std::vector<Snapshot>> out;
  for (const auto& c : cycles_)
    if (static_cast<int>(c.size()) == cfg_.samples_per_cycle) out.push_back(c);
  while (static_cast<int>(out.size()) > cfg_.keep_cycles) out.erase(out.begin());
  return out;
}

PatternResult classifyPatterns(const PatternSampler& sampler, double width, double container_height,
                               double d, bool periodic_x) {
  PatternResult r;
  const auto cycles = sampler.cycles();
  if (cycles.size() < 4) return r;
  const int S = sampler.config().samples_per_cycle;
  // The sampled phase with the highest mean centre of mass: the free flight.
  int best = 0;
  double best_h = -1e300;
  for (int k = 0; k < S; ++k) {
    double h = 0;
    for (const auto& c : cycles) {
      const Snapshot& s = c[k];
      h += std::accumulate(s.z.begin(), s.z.end(), 0.0) / std::max(1, s.size());
    }
    if (h > best_h) {
      best_h = h;
      best = k;
    }
  }
  std::vector<Snapshot> same_phase;
  std::vector<SurfaceProfile> profiles;
  for (const auto& c : cycles) {
    same_phase.push_back(c[best]);
    profiles.push_back(surfaceProfile(c[best], width, d, periodic_x));
  }
  r.available = true;
  r.cycles = static_cast<int>(cycles.size());
  r.phase = static_cast<double>(best) / S;
  r.surface_wave = detectStandingWave(profiles);
  r.kinks = detectKinks(profiles);
  r.state = classifyState(same_phase, width, d, periodic_x);
  r.within_cycle = classifyWithinCycles(cycles, width, container_height, d, periodic_x);
  return r;
}

}  // namespace granwave
