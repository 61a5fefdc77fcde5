#pragma once
// Checkpoints of one particle run (`granwave simulate --checkpoint-every S`), so that a run
// killed at any moment restarts where its last checkpoint stood and ends bit-identical to an
// uninterrupted run. Two files beside the run file RUN.h5:
//   RUN.h5.checkpoint         HDF5: what the run is (scene, options, build), the engine's
//                             state, each accumulating observer's state, the cost so far;
//   RUN.h5.checkpoint-K.h5md  the run file as it stood at checkpoint K (the state file names
//                             it; HDF5 guarantees nothing for a file killed while open).
// The copy is written first and the state file last, each atomically, so a kill at any
// instant leaves a consistent pair: the older one until the new state file is in place.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "particles/Checkpointable.hpp"
#include "particles/EngineState.hpp"

namespace granwave {

class EdSimulation;
class H5mdWriter;

// A checkpoint that cannot be taken, read or continued (the lock is held, a file is damaged or
// belongs to another run, the disk is full). Not a result of the run: the command exits with
// 75 and a study does not cache it, so the run is tried again once the cause is gone.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the run has accumulated besides the engine and the observers.
struct CheckpointLedger {
  double initial_energy = 0;                 // J, for the energy balance of the summary
  double wall_seconds = 0, cpu_seconds = 0;  // spent before this checkpoint, all segments
  std::uint64_t checkpoints = 0;             // written so far (names the copy)
};

struct LoadedCheckpoint {
  EngineState engine;
  CheckpointLedger ledger;
  std::string run_copy;  // empty if the run writes no run file
};

using NamedCheckpointables = std::vector<std::pair<std::string, Checkpointable*>>;

class RunCheckpoint {
 public:
  // `identity` says what the run is (canonical scene, options, build); a checkpoint is only
  // continued by a run of the same identity.
  // Takes RUN.h5.lock (flock, released even on SIGKILL): two processes writing the same
  // run would destroy each other's checkpoints. CheckpointError if another holds it.
  RunCheckpoint(std::string run_path, std::string identity);
  ~RunCheckpoint();
  RunCheckpoint(const RunCheckpoint&) = delete;
  RunCheckpoint& operator=(const RunCheckpoint&) = delete;

  const std::string& statePath() const { return state_path_; }
  bool exists() const;

  // Saves the engine, the run file (through `writer`, may be null) and the observers as
  // checkpoint ledger.checkpoints + 1, and returns that number. CheckpointError if it
  // cannot (e.g. the disk is full); the previous checkpoint then stays valid.
  std::uint64_t save(const EdSimulation& sim, H5mdWriter* writer,
                     const NamedCheckpointables& observers, CheckpointLedger ledger);
  // Restores the observers and returns the rest. CheckpointError naming the file if it is
  // damaged or belongs to another scene, options or build.
  LoadedCheckpoint load(const NamedCheckpointables& observers) const;
  // After the run has finished: removes the state file and every copy. (The lock file goes
  // when this object does.)
  void remove() const;

 private:
  std::string copyPath(std::uint64_t k) const;
  void removeCopiesExcept(const std::string& keep) const;
  std::string run_path_, state_path_, identity_;
  int lock_ = -1;
};

// The cost (wall, cpu seconds) a checkpointed run had spent before its last checkpoint;
// {0, 0} if `run_path` has no readable checkpoint. For the study's cost of a resumed run.
std::pair<double, double> checkpointedCost(const std::string& run_path);

}  // namespace granwave
