#pragma once
// LAMMPS dump, text ("dump custom" as LAMMPS writes it and `read_dump`, OVITO, ASE's
// lammps-dump-text reader and MDAnalysis's LAMMPSDUMP reader read it). One block per frame:
//
//   ITEM: TIMESTEP
//   k                                       (the run file's record index)
//   ITEM: NUMBER OF ATOMS
//   N
//   ITEM: BOX BOUNDS X ff Z                 (X, Z: "pp" periodic, "ff" walls)
//   0 Lx
//   -d/2 d/2
//   z_b z_b+Lz                              (the container where the plate is at this frame)
//   ITEM: ATOMS id type mass radius x y z vx vy vz omegax omegay omegaz
//   1 1 m d/2 x 0 z vx 0 vz 0 omega 0       (one line per disk, ids from 1)
//
// Numbers in SI, LAMMPS's `units si` (m, kg, s, m/s, rad/s), lab frame; the shortest
// decimals that read back to the run file's doubles. Exactly nine header lines per frame:
// MDAnalysis's reader counts lines, so no optional ITEM (TIME, UNITS) is written; a frame's
// time is k / (M f) (the run file's record interval).
#include <memory>
#include <string>

#include "exports/TrajectoryWriter.hpp"

namespace granwave {

std::unique_ptr<TrajectoryWriter> makeLammpsDumpWriter(const std::string& path,
                                                       const std::string& target,
                                                       const TrajectoryHeader& header);

}  // namespace granwave
