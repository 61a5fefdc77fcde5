#pragma once
// The surface waves of a grid point from the space-time spectrum of its runs' surfaces
// (coarse_grain/SurfaceWaveSpectrum.hpp; FIELDS.h5 /surface), beside the yes/no detector the
// diagrams keep: the share of spectrum windows with an f/2 standing wave pooled over the
// seeds, and the mean amplitude and wavelength of the seeds' standing modes.
#include <string>
#include <vector>

#include "studies/runner/RunRequest.hpp"

namespace granwave {

struct SpectrumWave {
  int runs = 0, windows = 0;                 // runs with a spectrum, windows pooled
  double wave_fraction = 0;                  // windows with a wave / windows
  double amplitude_d = 0, wavelength_d = 0;  // means over the runs with a spectrum
  bool measured() const { return windows > 0; }
};

// Over the finished runs among `records` (one per seed).
SpectrumWave spectrumWave(const std::vector<const RunRecord*>& records);
std::string describe(const SpectrumWave& s);

}  // namespace granwave
