#pragma once
// GSD (General Simulation Data, the file format of HOOMD-blue; file layer 2.0, "hoomd"
// schema 1.4), read by gsd.hoomd (Debian python3-gsd), OVITO and MDAnalysis's GSD reader.
// Debian packages no GSD C library, so the file layer is written here after its
// specification (gsd.readthedocs.io, "File layer"; read back in tests by gsd's own reader):
//
//   header (256 bytes)   magic 0x65DF65DF65DF65DF, index and namelist locations and sizes,
//                        schema_version 1.4, gsd_version 2.0, application "granwave <v>",
//                        schema "hoomd" (integers little-endian, as the format's C structs)
//   data chunks          in frame order, each chunk's bytes as an N x M C array
//   index block          32-byte entries {frame, N, location, M, id, type, flags = 0},
//                        sorted by frame, then by name id; a zeroed entry ends it
//   namelist block       the chunk names, each ended by a 0 byte, in id order, then 0
//                        bytes to a multiple of 64 (at least one: the empty name ends it)
//
// Chunks (hoomd schema; a chunk absent from frame i > 0 takes frame 0's value):
//   every frame      configuration/step (uint64, the run file's record index),
//                    particles/position, particles/velocity (float32 [N][3]),
//                    log/time (float64, s), log/plate_height (float64, m, z_b, lab frame),
//                    log/particles/angular_velocity (float64 [N][3], (0, omega, 0) rad/s)
//   frame 0 only     configuration/dimensions (uint8, 3), configuration/box (float32
//                    [Lx, d, Lz, 0, 0, 0]), particles/N (uint32), particles/types ("disk"),
//                    particles/typeid (uint32, 0), particles/mass (float32, kg),
//                    particles/diameter (float32, m)
//
// SI numbers. HOOMD's box is centred on the origin, so positions are in the container's
// frame: (x - Lx/2, 0, z - z_b - Lz/2), the plate at -Lz/2 and the lid at Lz/2 in every
// frame; the lab frame's z is position z + log/plate_height + Lz/2.
#include <memory>
#include <string>

#include "exports/TrajectoryWriter.hpp"

namespace granwave {

std::unique_ptr<TrajectoryWriter> makeGsdWriter(const std::string& path, const std::string& target,
                                                const TrajectoryHeader& header);

}  // namespace granwave
