#pragma once
// Reads a granwave H5MD run (layout in H5mdLayout.hpp) back: the scene text, box,
// provenance, trajectory frames as Snapshots, and observables as time series. Opening
// checks that the file is a granwave H5MD run with consistent shapes and throws a one-line
// h5::H5Error naming the file otherwise. A run marked completed=0 (interrupted) is still
// readable; completed() tells.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "particles/H5mdLayout.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

// One observable over the whole run. Counters are converted to double (exact below 2^53).
struct TimeSeries {
  std::vector<std::int64_t> step;
  std::vector<double> time;  // s
  std::vector<double> value;
};

class H5mdReader {
 public:
  explicit H5mdReader(const std::string& path);
  ~H5mdReader();
  H5mdReader(H5mdReader&&) noexcept;
  H5mdReader& operator=(H5mdReader&&) noexcept;

  const std::string& path() const;
  const std::string& sceneToml() const;
  const BoxInfo& box() const;  // width/height/thickness from the first frame (0 if none)
  const RunProvenance& provenance() const;
  bool completed() const;              // false if completed = 0 or absent
  const std::string& summary() const;  // empty if none

  std::size_t frameCount() const;   // trajectory frames
  std::size_t recordCount() const;  // observable records (>= frames)
  int particleCount() const;

  // Frame i: positions, velocities, omegas, step, time, and the observables (and plate
  // height) of the record with the same step, if there is one. std::out_of_range if i is
  // not below frameCount().
  Snapshot frame(std::size_t i) const;

  // "kinetic_energy", ...: any scalar series under /observables; "collisions/pair" (or
  // wall, tc_elastic, rests) for a column of the collisions table.
  TimeSeries observable(const std::string& name) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace granwave
