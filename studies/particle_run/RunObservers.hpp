#pragma once
// Two observers of a particle run that `granwave simulate` adds beside the run file and the
// live fields: the centre-of-mass height of every record (for the period in the summary) and
// the pair impacts pooled over the fields' cycles (for the momentum-transfer study's
// binary-impact estimate, docs/studies.md). Both are saved with a checkpoint.
#include <string>
#include <vector>

#include "coarse_grain/PhaseAverager.hpp"
#include "particles/Checkpointable.hpp"
#include "particles/PairImpactHistogram.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

// The centre-of-mass height at every record.
class CenterOfMassSeries : public SnapshotObserver, public Checkpointable {
 public:
  void observe(const Snapshot& s) override { height.push_back(s.obs.center_of_mass_height); }
  void saveState(h5::File& file, const std::string& group) const override;
  void restoreState(const h5::File& file, const std::string& group) override;
  std::vector<double> height;
};

// The normal speeds of the pair impacts over the fields' phase window and pooled cycles: from
// the averager's first pooled cycle, known once the layer is steady, to its last whole cycle.
class PooledPairImpacts : public SnapshotObserver {
 public:
  PooledPairImpacts(const PhaseAverager& averager, double frequency);
  void observe(const Snapshot&) override;
  PairImpactHistogram histogram;

 private:
  const PhaseAverager& averager_;
  double frequency_;
};

}  // namespace granwave
