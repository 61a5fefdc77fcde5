#pragma once
// The fields file (HDF5) and its XDMF sidecar for ParaView. Layout (docs/fields.md):
//   /grid/x [nx], /grid/z [nz]                     cell centres, m (lab frame)
//   /fields/<name> [phase][z][x]                   count, area_fraction, velocity_x,
//                                                  velocity_z, temperature, rotational_temperature
//   /profiles/<name> [phase][z]                    temperature, velocity_z, rms_velocity_x,
//                                                  area_fraction
//   /blocks/profiles/<name> [block][phase][z]      the same per block of cycles
//   /phases/{time, phase, plate_height, center_of_mass_height, front_height,
//            front_peak_temperature} [phase]
//   /fronts/<column> [episode]                     first_phase, last_phase, speed, speed_error,
//                                                  fit_error, block_spread, blocks_used,
//                                                  gas_velocity_ahead, speed_relative,
//                                                  peak_temperature, start_above_plate,
//                                                  from_impact (1/0)
//   /xdmf/pNNN/{area_fraction, temperature [nz][1][nx], velocity [nz][1][nx][3]}
//   /parameters                                    attributes; scene (TOML text)
// Units as "unit" attributes. Written atomically; the sidecar FIELDS.xdmf after the file.
#include <string>

#include "coarse_grain/FieldsAnalysis.hpp"

namespace granwave {

inline constexpr const char* kFieldsFormat = "granwave-fields-1";

void writeFieldsFile(const std::string& path, const FieldsAnalysis& analysis);
// Path of the XDMF sidecar for a fields file (same name, .xdmf).
std::string xdmfSidecarPath(const std::string& fields_path);

}  // namespace granwave
