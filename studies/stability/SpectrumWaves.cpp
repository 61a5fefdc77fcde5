#include "studies/stability/SpectrumWaves.hpp"

#include <fmt/format.h>

#include "coarse_grain/SurfaceWavesFile.hpp"

namespace granwave {

SpectrumWave spectrumWave(const std::vector<const RunRecord*>& records) {
  SpectrumWave s;
  int waves = 0;
  for (const RunRecord* r : records) {
    if (!r->ok) continue;
    const SurfaceWaveAnalysis a = readSurfaceWaves(r->fieldsPath());
    if (!a.available) continue;
    ++s.runs;
    const int n = static_cast<int>(a.windows.size());
    s.windows += n;
    waves += a.waveWindows();
    s.amplitude_d += a.amplitude_d;
    s.wavelength_d += a.wavelength_d;
  }
  if (s.runs == 0) return s;
  s.wave_fraction = s.windows > 0 ? static_cast<double>(waves) / s.windows : 0;
  s.amplitude_d /= s.runs;
  s.wavelength_d /= s.runs;
  return s;
}

std::string describe(const SpectrumWave& s) {
  if (!s.measured()) return "–";
  return fmt::format("f/2 wave in {:.0f} % of {} windows; {:.2f} d, lambda {:.0f} d",
                     100 * s.wave_fraction, s.windows, s.amplitude_d, s.wavelength_d);
}

}  // namespace granwave
