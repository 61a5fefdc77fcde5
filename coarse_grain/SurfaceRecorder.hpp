#pragma once
// Records the layer's surface h(x) (LayerSurface.hpp) at every recorded phase of the last
// `keep_cycles` drive cycles of a run, for the space-time spectrum of its surface waves
// (SurfaceWaveSpectrum.hpp). An observer of `granwave simulate --fields`; saved with
// checkpoints, so a continued run records exactly what an uninterrupted one would. The 2D
// continuum hands it the surfaces of its fields (`record`), so both are measured alike.
#include <deque>
#include <string>
#include <vector>

#include "coarse_grain/LayerSurface.hpp"
#include "particles/Checkpointable.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

struct SurfaceRecorderConfig {
  int records_per_cycle = 100;  // M of the run
  int keep_cycles = 160;        // the newest whole cycles kept (memory: cycles x M x columns)
  double width = 0, diameter = 0;
  bool periodic_x = false;
  LayerSurfaceOptions surface;
};

// h(x, t) of whole consecutive cycles: height[((c * M) + phase) * columns + i] in m above the
// plate, cycle c of the run = first_cycle + c.
struct SurfaceSeries {
  int columns = 0, records_per_cycle = 0, cycles = 0;
  long first_cycle = 0;
  double column_width = 0, diameter = 0;
  bool periodic_x = false;
  std::vector<double> height;
  std::vector<double> bulk_area_fraction;  // [c * M + phase]
  double at(int c, int phase, int i) const {
    return height[(static_cast<std::size_t>(c) * records_per_cycle + phase) * columns + i];
  }
};

class SurfaceRecorder : public SnapshotObserver, public Checkpointable {
 public:
  explicit SurfaceRecorder(const SurfaceRecorderConfig& config);
  void observe(const Snapshot& s) override;
  // One record's surface, measured elsewhere (a continuum's field: layerSurfaceOfField), at
  // record `phase` of drive cycle `cycle`; its profile must have the recorder's columns.
  void record(long cycle, int phase, const LayerSurface& surface);
  void saveState(h5::File& file, const std::string& group) const override;
  void restoreState(const h5::File& file, const std::string& group) override;
  // The kept whole cycles from run cycle `from` on (all kept ones if they start later).
  SurfaceSeries series(long from = 0) const;
  const SurfaceRecorderConfig& config() const { return cfg_; }

 private:
  struct Cycle {
    long index = 0;
    int filled = 0;  // records seen, in phase order
    std::vector<double> height, bulk;
  };
  SurfaceRecorderConfig cfg_;
  int columns_ = 0;
  std::deque<Cycle> cycles_;
};

}  // namespace granwave
