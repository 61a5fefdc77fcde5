#pragma once
// The study's run cache, OUTDIR/runs/. A run is named by a hash of what determines its
// result: the kind, the fully resolved scene (canonical TOML), the fields window and the
// build of granwave (a hash of the executable), so a run is reused only if the same build
// would repeat it bit for bit. A run counts as done once its record file (<stem>.done) exists;
// the record is written atomically after the run's own (atomic) outputs, so an interrupted
// study resumes with exactly the runs it finished. Failed runs (collapse, solver failure)
// are recorded too: they are results (where methods fail), and deterministic.
#include <functional>
#include <string>

#include "studies/runner/RunRequest.hpp"

namespace granwave {

class RunCache {
 public:
  // True if an output file of a finished run can be read (its format's reader opens it).
  using ReadableCheck = std::function<bool(const std::string& path)>;

  // With `readable`, a record whose output is no longer readable (truncated, damaged since)
  // does not count: the run is made again and its output replaced, as for a removed output.
  RunCache(std::string directory, std::string build_id, ReadableCheck readable = {});

  // A cache only looked into (granwave study --plan): the directory is not made.
  static RunCache lookOnly(std::string directory, std::string build_id,
                           ReadableCheck readable = {});

  const std::string& directory() const { return directory_; }
  // The record with its stem filled in (and ok/cpu/... if it is done). A particle run's scene
  // gets the trajectory stride that keeps its first and last frame only (RunCache.cpp).
  RunRecord record(const RunRequest& request) const;
  // True if the run is done; fills the outcome fields of `record`.
  bool load(RunRecord& record) const;
  void store(const RunRecord& record) const;

 private:
  struct LookOnly {};
  RunCache(LookOnly, std::string directory, std::string build_id, ReadableCheck readable);
  bool usable(const std::string& path) const;

  std::string directory_, build_id_;
  ReadableCheck readable_;
};

// FNV-1a 64-bit hash of the running executable's bytes, as 16 hex digits.
std::string buildIdentity();

}  // namespace granwave
