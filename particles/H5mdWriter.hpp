#pragma once
// Records a particle run as an H5MD 1.1 file (layout in H5mdLayout.hpp) that MDAnalysis,
// h5py and h5ls open directly. Observables are stored for every snapshot, trajectories
// (positions, velocities, angular velocities, box) for every k-th one. The file is written
// through an AtomicFile: it appears at its path only when finish() is called; if the writer
// is destroyed unfinished (an exception), nothing is left behind.
#include <cstddef>
#include <memory>
#include <string>

#include "particles/H5mdLayout.hpp"
#include "particles/PairImpactHistogram.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

class H5mdWriter : public SnapshotObserver {
 public:
  // Starts the file (H5MD header, box, scene, provenance). trajectory_stride k >= 1: a
  // snapshot goes into the trajectory when snapshot.step % k == 0. Throws h5::H5Error.
  H5mdWriter(std::string path, std::string scene_toml, RunProvenance provenance, BoxInfo box,
             int trajectory_stride);
  // Continues the run file from a copy saved by checkpoint() (a restarted run): the next
  // observe() appends after the copy's records; the result is the file an uninterrupted
  // run writes, dataset for dataset. Throws h5::H5Error if the copy is not such a file.
  H5mdWriter(std::string path, const std::string& checkpoint_copy, BoxInfo box,
             int trajectory_stride);
  ~H5mdWriter() override;
  H5mdWriter(const H5mdWriter&) = delete;
  H5mdWriter& operator=(const H5mdWriter&) = delete;

  // Appends one record. All particle vectors must have the same length, constant over the
  // run (std::invalid_argument otherwise). std::logic_error after finish().
  void observe(const Snapshot& snapshot) override;

  // Marks the run completed (1) or not (0), stores `summary` if non-empty, and publishes
  // the file atomically at its path, or at final_path_override if that is non-empty (an
  // interrupted run saved as RUN.h5.interrupted).
  void finish(bool complete, const std::string& summary = "",
              const std::string& final_path_override = "");

  // Stores the run's pair-impact normal-speed histogram at h5md::kPairImpacts (once, before
  // finish(); std::logic_error otherwise).
  void writePairImpacts(const PairImpactHistogram& impacts);

  // Writes out the buffered observables and saves a copy of the file as it is now at
  // `copy_path` (atomically), for a restart to continue from.
  void checkpoint(const std::string& copy_path);

  const std::string& path() const;
  std::size_t recordCount() const;
  std::size_t frameCount() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace granwave
