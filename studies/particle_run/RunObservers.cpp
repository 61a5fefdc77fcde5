#include "studies/particle_run/RunObservers.hpp"

#include "h5/File.hpp"

namespace granwave {

namespace {

PairImpactBins pooledBins(const PhaseAveragerConfig& c, double frequency) {
  PairImpactBins b;
  b.speed_max = 2.0;  // m/s; 5 mm/s bins resolve the wet law's onset at ~0.07 m/s
  b.speed_bins = 400;
  b.period = c.cycles_per_window / frequency;
  b.phase_bins = c.samples_per_cycle * c.cycles_per_window;
  b.start_time = 1e300;  // until the layer is steady
  b.end_time = c.total_cycles / frequency;
  return b;
}

}  // namespace

void CenterOfMassSeries::saveState(h5::File& file, const std::string& group) const {
  file.createGroup(group);
  file.writeDataset(group + "/height", height, {height.size()});
}

void CenterOfMassSeries::restoreState(const h5::File& file, const std::string& group) {
  height = file.readDataset<double>(group + "/height");
}

PooledPairImpacts::PooledPairImpacts(const PhaseAverager& averager, double frequency)
    : histogram(pooledBins(averager.config(), frequency)),
      averager_(averager),
      frequency_(frequency) {}

void PooledPairImpacts::observe(const Snapshot&) {
  const int first = averager_.firstPooledCycle();
  if (first >= 0) histogram.startAt(first / frequency_);
}

}  // namespace granwave
