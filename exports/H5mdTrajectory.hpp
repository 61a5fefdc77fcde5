#pragma once
// The trajectory as H5MD 1.1 in the layout MDAnalysis's H5MD reader opens by itself,
// `MDAnalysis.Universe("RUN.h5md")`. The run file is H5MD too, in SI (lengths in m, the
// scene's unit); MDAnalysis 2.4 accepts only nm, Angstrom, pm and fm as lengths and finds
// the particle count only in a group named "trajectory". So this copy differs from the run
// file in exactly those two points (the .h5md extension is what MDAnalysis recognises):
//
//   /h5md                       version = [1, 1]; author/name; creator/name = "granwave",
//                               version; modules/units (version [1, 0], system "SI")
//   /particles/trajectory/box   dimension = 3, boundary = [x, "none", z]
//     edges/{step,time,value}   value [frames][3][3] = diag(Lx, d, Lz), nm
//   /particles/trajectory/position/{step,time,value}          [frames][N][3], nm
//   /particles/trajectory/velocity/{step,time,value}          [frames][N][3], m s-1
//   /particles/trajectory/angular_velocity/{step,time,value}  [frames][N][3], rad s-1
//   /observables/plate_height/{step,time,value}               [frames], nm
//
// step: int64, the run file's record index; time: double, unit "s". Lab frame, as in the
// run file; every value dataset carries its unit, which MDAnalysis converts to its own
// (Angstrom, ps). Observables are written at the frames only, because MDAnalysis reads
// /observables/<name>/value at the frame's index.
#include <memory>
#include <string>

#include "exports/TrajectoryWriter.hpp"

namespace granwave {

inline constexpr double kH5mdExportNanometresPerMetre = 1e9;

std::unique_ptr<TrajectoryWriter> makeH5mdWriter(const std::string& path, const std::string& target,
                                                 const TrajectoryHeader& header);

}  // namespace granwave
