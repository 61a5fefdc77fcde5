#pragma once
// The trajectory of a run in the formats of the field's viewers and analysis tools
// (docs/commands.md, "granwave export" and "Viewers"). One header per format owns its
// layout and writer: ExtendedXyz.hpp (ASE, OVITO), GsdTrajectory.hpp (HOOMD-blue, OVITO,
// MDAnalysis), LammpsDump.hpp (LAMMPS, OVITO, ASE, MDAnalysis), H5mdTrajectory.hpp (MDAnalysis's
// H5MD reader, which refuses the run file's metres). A writer is handed the frames in order
// and then closed; `granwave export` publishes the file atomically (files/AtomicOutput.hpp).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "particles/H5mdLayout.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

// What every frame shares. SI units, as in the run file.
struct TrajectoryHeader {
  BoxInfo box;          // the container at rest (plate at z = 0), one diameter thick in y
  double diameter = 0;  // m
  double mass = 0;      // kg, of one disk
  std::string version;  // granwave's
  std::string author;   // H5MD author; empty: $USER, else "unknown"
};

class TrajectoryWriter {
 public:
  virtual ~TrajectoryWriter() = default;
  // The next frame (steps increasing). std::system_error or h5::H5Error on a failed write.
  virtual void write(const Snapshot& frame) = 0;
  // Completes the file (closing blocks, index, buffers) and reports a failed write.
  virtual void close() = 0;
};

enum class TrajectoryFormat { ExtendedXyz, Gsd, LammpsDump, H5md };

struct TrajectoryFormatInfo {
  TrajectoryFormat format;
  std::string_view name;       // --format value
  std::string_view extension;  // default output extension, with the dot
  std::string_view label;      // for the summary: "extended XYZ, SI units"
};

// Every format, in the order --help lists them.
const std::vector<TrajectoryFormatInfo>& trajectoryFormats();
const TrajectoryFormatInfo& trajectoryFormat(TrajectoryFormat format);

// A writer of `format` into `path`; messages name `target` (the published name).
std::unique_ptr<TrajectoryWriter> makeTrajectoryWriter(TrajectoryFormat format,
                                                       const std::string& path,
                                                       const std::string& target,
                                                       const TrajectoryHeader& header);

}  // namespace granwave
