#pragma once
// Pattern and state classification of a run (docs/classification.md):
// an observer keeps the snapshots of the last `keep_cycles` steady cycles at
// `samples_per_cycle` phases; classification then looks at the phase where the centre of
// mass is highest (the free flight, where the paper inspects the layer), across those
// consecutive cycles: standing surface waves, kinks, and crystal / amorphous / liquid-like;
// and, each cycle on its own over all its sampled phases, the within-cycle state.
#include <deque>
#include <vector>

#include "coarse_grain/KinkDetector.hpp"
#include "coarse_grain/StateClassifier.hpp"
#include "coarse_grain/SurfaceWaveDetector.hpp"
#include "coarse_grain/WithinCycleState.hpp"
#include "particles/Checkpointable.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

struct PatternSamplerConfig {
  int records_per_cycle = 100;  // M of the run
  int samples_per_cycle = 10;   // phases kept per cycle
  int keep_cycles = 16;         // last cycles kept (even: period-2 alternation pairs up)
};

class PatternSampler : public SnapshotObserver, public Checkpointable {
 public:
  explicit PatternSampler(const PatternSamplerConfig& c) : cfg_(c) {}
  void observe(const Snapshot& s) override;
  void saveState(h5::File& file, const std::string& group) const override;
  void restoreState(const h5::File& file, const std::string& group) override;
  // Cycles kept, oldest first; each holds samples_per_cycle snapshots (a partial last
  // cycle is dropped).
  std::vector<std::vector<Snapshot>> cycles() const;
  const PatternSamplerConfig& config() const { return cfg_; }

 private:
  PatternSamplerConfig cfg_;
  std::deque<std::vector<Snapshot>> cycles_;
  long current_ = -1;
};

struct PatternResult {
  bool available = false;  // enough cycles were kept
  double phase = 0;        // t/T of the classified phase
  int cycles = 0;
  SurfaceWaveResult surface_wave;
  KinkResult kinks;
  StateResult state;               // the bond criterion, over the kept cycles
  WithinCycleResult within_cycle;  // the within-cycle criterion, each kept cycle on its own
};

// `container_height` places the lid (plate + height) for the within-cycle lid contact.
PatternResult classifyPatterns(const PatternSampler& sampler, double width, double container_height,
                               double diameter, bool periodic_x);

}  // namespace granwave
