#pragma once
// A histogram of the normal relative speeds of pair (particle-particle) impacts, taken before
// the collision, in bins of the drive's phase (docs/physics.md, "Pair impact speeds"). It is a
// read-only observer of the engine's pair collisions (EdSimulation::setPairImpactObserver):
// with none set the engine pays one untaken branch per pair collision. Impacts outside
// [start_time, end_time) (the transient, a last partial cycle) are not counted, nor those
// outside [z_min, z_max] (lab frame).
//
// What it is for: the collision-weighted mean of any function of the normal speed over the
// impacts of a phase window, e.g. <(1 + e_dry(v_n)) / (1 + e_wet(v_n))>, the binary-collision
// estimate of the momentum-transfer ratio r_x at the speeds the layer's impacts really have.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "particles/Checkpointable.hpp"

namespace granwave {

struct PairImpact {
  double time = 0;          // s
  double normal_speed = 0;  // m/s, approach speed along the line of centres, > 0
  double height = 0;        // m, lab frame, of the contact point
  bool tc_elastic = false;  // made elastic by the TC model
};

// Read-only consumer of pair impacts; never changes the simulation.
class PairImpactObserver {
 public:
  virtual ~PairImpactObserver() = default;
  virtual void pairImpact(const PairImpact& impact) = 0;
};

struct PairImpactBins {
  double speed_max = 2.0;  // m/s; faster impacts go to the last (overflow) bin
  int speed_bins = 100;
  double period = 0;   // s, the window of phases (cycles per window / f); 0: no phases
  int phase_bins = 1;  // bins over the window
  double start_time = 0, end_time = 1e300;  // s
  double z_min = -1e300, z_max = 1e300;
};

// Saved (checkpoints, run files) as a group: dataset `counts` uint64 [phase_bins][speed_bins]
// and the attributes speed_max (m s-1), speed_bins, phase_bins, period, start_time, end_time,
// z_min, z_max (m) and total (docs/commands.md, "Run file").
class PairImpactHistogram final : public PairImpactObserver, public Checkpointable {
 public:
  // std::invalid_argument on bins that are not positive or a negative period.
  explicit PairImpactHistogram(const PairImpactBins& bins);
  // The histogram saved under `group`; h5::H5Error naming the file and object if it is not one.
  static PairImpactHistogram read(const h5::File& file, const std::string& group);
  void pairImpact(const PairImpact& impact) override;
  // Counts only impacts from `time` on (the start of the pooled cycles, known once the layer
  // is steady).
  void startAt(double time) { bins_.start_time = time; }

  void saveState(h5::File& file, const std::string& group) const override;
  // h5::H5Error if the saved bins differ from this histogram's (other than start_time).
  void restoreState(const h5::File& file, const std::string& group) override;

  const PairImpactBins& bins() const { return bins_; }
  // Counts [phase bin][speed bin]; the last speed bin also holds the overflow.
  const std::vector<std::uint64_t>& counts() const { return counts_; }
  std::uint64_t count(int phase_bin, int speed_bin) const {
    return counts_[static_cast<std::size_t>(phase_bin) * bins_.speed_bins + speed_bin];
  }
  std::uint64_t total() const { return total_; }
  double speedBinCentre(int k) const { return (k + 0.5) * bins_.speed_max / bins_.speed_bins; }
  // Collision-weighted mean of f(v_n) over the phase bins for which `use` is true (all if
  // empty), with v_n at the bin centres; NaN without impacts.
  double weightedMean(const std::function<double(double)>& f,
                      const std::vector<bool>& use = {}) const;
  // Counts per speed bin, summed over the phase bins for which `use` is true (all if empty).
  std::vector<std::uint64_t> speedCounts(const std::vector<bool>& use = {}) const;

 private:
  PairImpactBins bins_;
  std::vector<std::uint64_t> counts_;
  std::uint64_t total_ = 0;
};

}  // namespace granwave
