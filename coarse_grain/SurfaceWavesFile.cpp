#include "coarse_grain/SurfaceWavesFile.hpp"

#include <cstdint>

namespace granwave {

namespace {

const std::string kWindows = std::string(kSurfaceGroup) + "/windows";

// The per-window values, one dataset each, in the order of SurfaceWindow.
template <class Get>
std::vector<double> column(const SurfaceWaveAnalysis& a, Get get) {
  std::vector<double> v;
  for (const SurfaceWindow& w : a.windows) v.push_back(static_cast<double>(get(w)));
  return v;
}

void putSeries(h5::File& f, const std::string& path, const std::vector<double>& v,
               const char* unit) {
  f.writeDataset(path, v, {v.size()});
  f.writeStringAttribute(path, "unit", unit);
}

void writeWindows(h5::File& f, const SurfaceWaveAnalysis& a) {
  f.createGroup(kWindows);
  putSeries(f, kWindows + "/first_cycle", column(a, [](auto& w) { return w.first_cycle; }), "1");
  putSeries(f, kWindows + "/dominant_mode", column(a, [](auto& w) { return w.dominant_mode; }),
            "1");
  putSeries(f, kWindows + "/subharmonic_share",
            column(a, [](auto& w) { return w.subharmonic_share; }), "1");
  putSeries(f, kWindows + "/standing_mode", column(a, [](auto& w) { return w.standing_mode; }),
            "1");
  putSeries(f, kWindows + "/amplitude_d", column(a, [](auto& w) { return w.amplitude_d; }), "d");
  putSeries(f, kWindows + "/noise_d", column(a, [](auto& w) { return w.noise_d; }), "d");
  putSeries(f, kWindows + "/crest_d", column(a, [](auto& w) { return w.crest_d; }), "d");
  putSeries(f, kWindows + "/harmonic_amplitude_d",
            column(a, [](auto& w) { return w.harmonic_amplitude_d; }), "d");
  putSeries(f, kWindows + "/wavenumber", column(a, [](auto& w) { return w.wavenumber; }), "m-1");
  putSeries(f, kWindows + "/wavelength_d", column(a, [](auto& w) { return w.wavelength_d; }), "d");
  putSeries(f, kWindows + "/wave", column(a, [](auto& w) { return w.wave; }), "1");
}

SurfaceWindow windowAt(const h5::File& f, std::size_t k) {
  auto get = [&](const char* name) { return f.readDataset<double>(kWindows + "/" + name).at(k); };
  SurfaceWindow w;
  w.first_cycle = static_cast<long>(get("first_cycle"));
  w.dominant_mode = static_cast<int>(get("dominant_mode"));
  w.subharmonic_share = get("subharmonic_share");
  w.standing_mode = static_cast<int>(get("standing_mode"));
  w.amplitude_d = get("amplitude_d");
  w.noise_d = get("noise_d");
  w.crest_d = get("crest_d");
  w.harmonic_amplitude_d = get("harmonic_amplitude_d");
  w.wavenumber = get("wavenumber");
  w.wavelength_d = get("wavelength_d");
  w.wave = get("wave") != 0;
  return w;
}

}  // namespace

void writeSurfaceWaves(h5::File& f, const SurfaceWaveAnalysis& a) {
  if (!a.available) return;
  const std::string g = kSurfaceGroup;
  f.createGroup(g);
  const auto i64 = [&](const char* name, long v) {
    f.writeAttribute<std::int64_t>(g, name, static_cast<std::int64_t>(v));
  };
  const auto real = [&](const char* name, double v) { f.writeAttribute<double>(g, name, v); };
  i64("columns", a.columns);
  i64("records_per_cycle", a.records_per_cycle);
  i64("window_cycles", a.window_cycles);
  i64("cycles", a.cycles);
  i64("periodic_x", a.periodic_x);
  i64("standing_mode", a.standing_mode);
  i64("recent_records", a.recent_records);
  real("width", a.width);
  real("diameter", a.diameter);
  real("amplitude_d", a.amplitude_d);
  real("amplitude_error_d", a.amplitude_error_d);
  real("noise_d", a.noise_d);
  real("wavelength_d", a.wavelength_d);
  real("wavelength_error_d", a.wavelength_error_d);
  real("subharmonic_share", a.subharmonic_share);
  real("subharmonic_share_error", a.subharmonic_share_error);
  real("wave_fraction", a.wave_fraction);
  real("mean_bulk_area_fraction", a.mean_bulk_area_fraction);
  writeWindows(f, a);
  putSeries(f, g + "/mode_wavenumber", a.mode_wavenumber, "m-1");
  putSeries(f, g + "/power_subharmonic", a.power_subharmonic, "m2");
  putSeries(f, g + "/power_harmonic", a.power_harmonic, "m2");
  putSeries(f, g + "/power_broadband", a.power_broadband, "m2");
  putSeries(f, g + "/frequency_over_f", a.frequency_over_f, "1");
  putSeries(f, g + "/temporal_power", a.temporal_power, "m2");
  f.writeDataset(g + "/recent_height", a.recent_height,
                 {static_cast<std::size_t>(a.recent_records), static_cast<std::size_t>(a.columns)});
  f.writeStringAttribute(g + "/recent_height", "unit", "m");
}

SurfaceWaveAnalysis readSurfaceWaves(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  SurfaceWaveAnalysis a;
  const std::string g = kSurfaceGroup;
  if (!f.exists(g)) return a;
  const auto i64 = [&](const char* name) { return f.readAttribute<std::int64_t>(g, name); };
  const auto real = [&](const char* name) { return f.readAttribute<double>(g, name); };
  a.available = true;
  a.columns = static_cast<int>(i64("columns"));
  a.records_per_cycle = static_cast<int>(i64("records_per_cycle"));
  a.window_cycles = static_cast<int>(i64("window_cycles"));
  a.cycles = static_cast<int>(i64("cycles"));
  a.periodic_x = i64("periodic_x") != 0;
  a.standing_mode = static_cast<int>(i64("standing_mode"));
  a.recent_records = static_cast<int>(i64("recent_records"));
  a.width = real("width");
  a.diameter = real("diameter");
  a.amplitude_d = real("amplitude_d");
  a.amplitude_error_d = real("amplitude_error_d");
  a.noise_d = real("noise_d");
  a.wavelength_d = real("wavelength_d");
  a.wavelength_error_d = real("wavelength_error_d");
  a.subharmonic_share = real("subharmonic_share");
  a.subharmonic_share_error = real("subharmonic_share_error");
  a.wave_fraction = real("wave_fraction");
  a.mean_bulk_area_fraction = real("mean_bulk_area_fraction");
  const std::size_t n = f.readDataset<double>(kWindows + "/first_cycle").size();
  for (std::size_t k = 0; k < n; ++k) a.windows.push_back(windowAt(f, k));
  a.mode_wavenumber = f.readDataset<double>(g + "/mode_wavenumber");
  a.power_subharmonic = f.readDataset<double>(g + "/power_subharmonic");
  a.power_harmonic = f.readDataset<double>(g + "/power_harmonic");
  a.power_broadband = f.readDataset<double>(g + "/power_broadband");
  a.frequency_over_f = f.readDataset<double>(g + "/frequency_over_f");
  a.temporal_power = f.readDataset<double>(g + "/temporal_power");
  a.recent_height = f.readDataset<double>(g + "/recent_height");
  return a;
}

}  // namespace granwave
