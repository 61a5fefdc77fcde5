#pragma once
// An observer that accumulates over the run (phase averages, kept snapshots, series) and so
// must be saved with a checkpoint and restored on restart for the run to end as an
// uninterrupted one would. Observers that only look at the current snapshot need neither.
// The observer is restored into an object built with the same configuration; a checkpoint
// is only continued by the same scene and options (RunCheckpoint checks that).
#include <string>

#include "h5/File.hpp"

namespace granwave {

class Checkpointable {
 public:
  virtual ~Checkpointable() = default;
  virtual void saveState(h5::File& file, const std::string& group) const = 0;
  // h5::H5Error naming the file and dataset if the saved state does not fit this object.
  virtual void restoreState(const h5::File& file, const std::string& group) = 0;
};

}  // namespace granwave
