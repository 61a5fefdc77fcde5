#pragma once
// Extended XYZ, the format of ASE (ase.io.extxyz), also read by OVITO. One block per frame:
//
//   N
//   Lattice="Lx 0 0 0 d 0 0 0 Lz" Properties=species:S:1:pos:R:3:velocities:R:3:
//     angular_velocity:R:3:radius:R:1 Time=t step=k plate_height=z_b units=SI pbc="X F Z"
//   X x 0 z vx 0 vz 0 omega 0 d/2          (one line per disk)
//
// SI units and the lab frame, as in the run file: the disks move in the x-z plane and spin
// about y; the cell is the container at rest (its bottom at z = 0; the plate is at
// plate_height). Numbers are the shortest decimals that read back to the run file's doubles.
#include <memory>
#include <string>

#include "exports/TrajectoryWriter.hpp"

namespace granwave {

std::unique_ptr<TrajectoryWriter> makeExtendedXyzWriter(const std::string& path,
                                                        const std::string& target,
                                                        const TrajectoryHeader& header);

}  // namespace granwave
