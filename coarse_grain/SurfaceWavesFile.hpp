#pragma once
// The /surface group of a fields file (FIELDS.h5; docs/fields.md): the surface waves of the
// run's layer from the space-time spectrum of its surface (SurfaceWaveSpectrum.hpp). This
// header owns the group's layout; it is written beside the rest of the fields and read by the
// studies.
#include <string>

#include "coarse_grain/SurfaceWaveSpectrum.hpp"
#include "h5/File.hpp"

namespace granwave {

inline constexpr const char* kSurfaceGroup = "/surface";

// Writes nothing when the analysis is not available (a run without a recorder).
void writeSurfaceWaves(h5::File& file, const SurfaceWaveAnalysis& analysis);

// available = false when the file has no /surface group (an older fields file).
SurfaceWaveAnalysis readSurfaceWaves(const std::string& fields_path);

}  // namespace granwave
