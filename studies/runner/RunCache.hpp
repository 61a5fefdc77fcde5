#pragma once
// The study's run cache, OUTDIR/runs/. A run is named by a hash of what determines its
// result: the kind, the fully resolved scene (canonical TOML), the fields window and the
// build of granwave (a hash of the executable), so a run is reused only if the same build
// would repeat it bit for bit. A run counts as done once its record file (<stem>.done) exists;
// the record is written atomically after the run's own (atomic) outputs, so an interrupted
// study resumes with exactly the runs it finished. Failed runs (collapse, solver failure)
// are recorded too: they are results (where methods fail), and deterministic.
#include <string>

#include "studies/runner/RunRequest.hpp"

namespace granwave {

class RunCache {
 public:
  RunCache(std::string directory, std::string build_id);

  const std::string& directory() const { return directory_; }
  // The record with its stem filled in (and ok/cpu/... if it is done). A particle run's scene
  // gets the trajectory stride that keeps its first and last frame only (RunCache.cpp).
  RunRecord record(const RunRequest& request) const;
  // True if the run is done; fills the outcome fields of `record`.
  bool load(RunRecord& record) const;
  void store(const RunRecord& record) const;

 private:
  std::string directory_, build_id_;
};

// FNV-1a 64-bit hash of the running executable's bytes, as 16 hex digits.
std::string buildIdentity();

}  // namespace granwave
