#include "coarse_grain/FieldsFile.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "coarse_grain/FieldsLayout.hpp"
#include "coarse_grain/SurfaceWavesFile.hpp"
#include "files/OutputPath.hpp"
#include "h5/AtomicFile.hpp"

namespace granwave {

namespace {

namespace L = fields_layout;
using Shape = h5::Shape;

void put(h5::File& f, const std::string& path, const std::vector<double>& v, const Shape& shape,
         const char* unit, h5::Storage storage = h5::Storage::contiguous) {
  f.writeDataset(path, v, shape, storage);
  f.writeStringAttribute(path, "unit", unit);
}

// [nz][1][nx] slab of phase `ph` of a [phase][z][x] field, as ParaView's XDMF reader wants.
std::vector<double> slab(const PhaseFields& p, const std::vector<double>& field, int ph) {
  const auto first = field.begin() + static_cast<long>(p.cell(ph, 0, 0));
  return {first, first + static_cast<long>(p.nz) * p.nx};
}

void writeXdmf(const std::string& xdmf_path, const std::string& h5_name, const FieldsAnalysis& a) {
  const FieldGrid& g = a.grid;
  const PhaseFields& p = a.pooled;
  std::string s;
  s += "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n";
  s += "<Grid Name=\"phases\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (int ph = 0; ph < p.phases; ++ph) {
    const std::string grp = fmt::format("/xdmf/p{:04d}", ph);
    s += fmt::format("<Grid Name=\"p{:04d}\" GridType=\"Uniform\">\n", ph);
    s += fmt::format("<Time Value=\"{:.9g}\"/>\n", a.phaseTime(ph));
    // Cell-centred data on a one-cell-thick slab: the mesh has (nz+1) x 2 x (nx+1) nodes.
    s += fmt::format("<Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"{} 2 {}\"/>\n", g.nz + 1,
                     g.nx + 1);
    s += "<Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n";
    s += fmt::format("<DataItem Dimensions=\"3\" Format=\"XML\">{:.9g} 0 {:.9g}</DataItem>\n", g.z0,
                     g.x0);
    s += fmt::format("<DataItem Dimensions=\"3\" Format=\"XML\">{:.9g} {:.9g} {:.9g}</DataItem>\n",
                     g.wz, a.context.diameter, g.wx);
    s += "</Geometry>\n";
    for (const char* name : {"area_fraction", "temperature"}) {
      s += fmt::format("<Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n", name);
      s += fmt::format(
          "<DataItem Dimensions=\"{} 1 {}\" NumberType=\"Float\" Precision=\"8\" "
          "Format=\"HDF\">{}:{}/{}</DataItem>\n</Attribute>\n",
          g.nz, g.nx, h5_name, grp, name);
    }
    s += "<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Cell\">\n";
    s += fmt::format(
        "<DataItem Dimensions=\"{} 1 {} 3\" NumberType=\"Float\" Precision=\"8\" "
        "Format=\"HDF\">{}:{}/velocity</DataItem>\n</Attribute>\n",
        g.nz, g.nx, h5_name, grp);
    s += "</Grid>\n";
  }
  s += "</Grid>\n</Domain>\n</Xdmf>\n";
  const std::string tmp = files::temporaryFor(xdmf_path);
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << s;
    out.flush();
    // A system_error (errno: disk full, permissions) marks this as a file failure, exit 74.
    if (!out) {
      const int error = errno ? errno : EIO;
      std::remove(tmp.c_str());
      throw std::system_error(error, std::generic_category(),
                              xdmf_path + ": cannot write the XDMF sidecar");
    }
  }
  std::filesystem::rename(tmp, xdmf_path);
}

// The live classification (/patterns, docs/classification.md): both solid criteria.
void writePatterns(h5::File& f, const PatternResult& pr) {
  const std::string& g = L::kPatterns;
  f.createGroup(g);
  f.writeAttribute<std::int64_t>(g, "available", pr.available ? 1 : 0);
  if (pr.available) {
    f.writeAttribute<double>(g, "phase", pr.phase);
    f.writeAttribute<std::int64_t>(g, "cycles", pr.cycles);
    f.writeAttribute<std::int64_t>(g, "surface_wave", pr.surface_wave.detected ? 1 : 0);
    f.writeAttribute<std::int64_t>(g, "surface_wave_mode", pr.surface_wave.mode);
    f.writeAttribute<double>(g, "surface_wave_wavelength_d", pr.surface_wave.wavelength_d);
    f.writeAttribute<double>(g, "surface_wave_amplitude_d", pr.surface_wave.amplitude_d);
    f.writeAttribute<double>(g, "surface_wave_alternation", pr.surface_wave.alternation_fraction);
    f.writeAttribute<std::int64_t>(g, "kinks", static_cast<std::int64_t>(pr.kinks.kink_x.size()));
    f.writeStringAttribute(g, "state", std::string(toString(pr.state.state)));
    f.writeAttribute<double>(g, "mean_abs_psi6", pr.state.mean_abs_psi6);
    f.writeAttribute<double>(g, "mean_relative_displacement_d",
                             pr.state.mean_relative_displacement_d);
    f.writeAttribute<double>(g, "bonds_kept", pr.state.bonds_kept);
    f.writeAttribute<double>(g, "bonds_kept_per_cycle", pr.state.bonds_kept_per_cycle);
    const WithinCycleResult& w = pr.within_cycle;
    f.writeStringAttribute(g, "within_cycle_state", std::string(toString(w.state)));
    f.writeAttribute<double>(g, "within_cycle_crystal_share", w.crystal_share);
    f.writeAttribute<double>(g, "within_cycle_amorphous_share", w.amorphous_share);
    f.writeAttribute<double>(g, "within_cycle_liquid_share", w.liquid_share);
    f.writeAttribute<double>(g, "within_cycle_coordination", w.coordination);
    f.writeAttribute<double>(g, "within_cycle_psi6", w.psi6);
    f.writeAttribute<double>(g, "within_cycle_compact_phase", w.compact_phase);
    f.writeAttribute<double>(g, "lid_row", w.lid_row);
    f.writeAttribute<double>(g, "lid_row_cycles", w.lid_row_cycles);
  }
}

// The period-2 state window by window (/period_doubling, docs/classification.md, "Layer
// state over time"): strengths, noise thresholds and the episodes (first cycle, cycles,
// period as rows of three).
void writePeriodDoubling(h5::File& f, const PeriodDoublingSeries& pd) {
  if (pd.f2_strength.empty()) return;
  const std::string& g = L::kPeriodDoubling;
  f.createGroup(g);
  put(f, g + "/" + L::kF2Strength, pd.f2_strength, {pd.f2_strength.size()}, "1");
  put(f, g + "/" + L::kNoiseStrength, pd.noise_strength, {pd.noise_strength.size()}, "1");
  put(f, g + "/" + L::kThreshold, pd.threshold, {pd.threshold.size()}, "1");
  std::vector<std::int64_t> episodes;
  for (const StateEpisode& e : pd.episodes)
    episodes.insert(episodes.end(), {e.first_cycle, e.cycles, e.period});
  f.writeDataset(g + "/" + L::kEpisodes, episodes, {pd.episodes.size(), 3});
  // cycles, cycles, period (counts)
  f.writeStringAttribute(g + "/" + L::kEpisodes, "unit", "1");
  f.writeAttribute<std::int64_t>(g, "window_cycles", pd.window_cycles);
  f.writeAttribute<std::int64_t>(g, "first_cycle", pd.first_cycle);
  f.writeAttribute<double>(g, "period2_share", pd.period2_share);
  f.writeAttribute<double>(g, "share_low", pd.share_low);
  f.writeAttribute<double>(g, "share_high", pd.share_high);
  f.writeAttribute<double>(g, "effective_windows", pd.effective_windows);
  f.writeAttribute<std::int64_t>(g, "switches", pd.switches);
}

// The fields conditioned on the layer's state (/states/period1, /states/period2; attributes
// windows and pooled_cycles); /states has windows_period1 and windows_period2 (-1: not measured).
void writeStates(h5::File& f, const FieldsAnalysis& a) {
  if (a.state_windows[0] < 0) return;
  f.createGroup(L::kStates);
  for (int k = 0; k < 2; ++k)
    f.writeAttribute<std::int64_t>(L::kStates, L::kStateWindows[k], a.state_windows[k]);
  for (const FieldsAnalysis& s : a.states) {
    const std::string root = L::stateRoot(s.state_period);
    f.createGroup(root);
    writePhaseProfiles(f, root, s.profiles());
    f.writeAttribute<std::int64_t>(root, L::kWindows, a.state_windows[s.state_period - 1]);
    f.writeAttribute<std::int64_t>(root, L::kPooledCycles, s.pooled_cycles);
  }
}

void writeParameters(h5::File& f, const FieldsAnalysis& a) {
  const std::string& par = L::kParameters;
  f.createGroup(par);
  f.writeStringAttribute(par, L::kFormat, kFieldsFormat);
  f.writeStringAttribute(par, L::kSource, a.context.source);
  f.writeAttribute<double>(par, L::kDiameter, a.context.diameter);
  f.writeAttribute<double>(par, L::kMass, a.context.mass);
  f.writeAttribute<double>(par, L::kFrequency, a.context.frequency);
  f.writeAttribute<double>(par, L::kAmplitude, a.context.amplitude);
  f.writeAttribute<double>(par, L::kT0, a.context.T0);
  f.writeAttribute<std::int64_t>(par, L::kSamplesPerCycle, a.samples_per_cycle);
  f.writeAttribute<std::int64_t>(par, L::kCyclesPerWindow, a.cycles_per_window);
  f.writeAttribute<std::int64_t>(par, L::kBlocks, a.blocks);
  f.writeAttribute<std::int64_t>(par, L::kDiscardedCycles, a.discarded_cycles);
  f.writeAttribute<std::int64_t>(par, L::kPooledCycles, a.pooled_cycles);
  f.writeAttribute<std::int64_t>(par, L::kLayerPeriod, a.context.layer_period);
  f.writeAttribute<std::int64_t>(par, L::kMinCount, a.params.min_count);
  f.writeAttribute<double>(par, L::kFrontThreshold, a.front_options.threshold);
  f.writeAttribute<double>(par, L::kFrontLayerMinAreaFraction,
                           a.front_options.layer_min_area_fraction);
  f.writeStringDataset(L::kScene, a.context.scene_toml);
}

}  // namespace

std::string xdmfSidecarPath(const std::string& fields_path) {
  std::filesystem::path p(fields_path);
  p.replace_extension(".xdmf");
  return p.string();
}

void writePhaseProfiles(h5::File& f, const std::string& root, const PhaseProfiles& p) {
  const std::size_t P = p.phases(), Z = p.rows(), B = p.blocks.size();
  f.createGroup(root + L::kProfiles);
  for (const L::FieldColumn& c : L::kProfileFields)
    if (!(p.pooled.*c.values).empty())
      put(f, root + L::kProfiles + "/" + c.name, p.pooled.*c.values, {P, Z}, c.unit,
          h5::Storage::compressed);
  if (B > 0) {
    f.createGroup(root + L::kBlockProfiles);
    for (const L::FieldColumn& c : L::kProfileFields) {
      std::vector<double> stacked;
      for (const PhaseFields& b : p.blocks)
        stacked.insert(stacked.end(), (b.*c.values).begin(), (b.*c.values).end());
      put(f, root + L::kBlockProfiles + "/" + c.name, stacked, {B, P, Z}, c.unit,
          h5::Storage::compressed);
    }
  }
  const std::string phases = root + L::kPhases + "/";
  f.createGroup(root + L::kPhases);
  put(f, phases + L::kTime, p.time, {P}, "s");
  put(f, phases + L::kPhase, p.phase, {P}, "1");
  put(f, phases + L::kPlateHeight, p.plate_height, {P}, "m");
  put(f, phases + L::kCenterOfMass, p.pooled.center_of_mass_height, {P}, "m");
  put(f, phases + L::kFrontHeight, p.front_height, {P}, "m");
  put(f, phases + L::kFrontPeak, p.front_peak_temperature, {P}, "1");
  for (const L::FieldColumn& c : L::kBudgetSeries)
    if (!(p.pooled.*c.values).empty()) put(f, phases + c.name, p.pooled.*c.values, {P}, c.unit);
  f.createGroup(root + L::kFronts);
  for (const L::FrontColumn& c : L::kFrontColumns) {
    std::vector<double> column;
    for (const FrontEpisode& e : p.fronts) column.push_back(c.get(e));
    put(f, root + L::kFronts + "/" + c.name, column, {p.fronts.size()}, c.unit);
  }
}

namespace {

// The cells of every phase, and their [nz][1][nx] copies per phase for ParaView (/xdmf).
void writeCells(h5::File& f, const FieldsAnalysis& a) {
  const PhaseFields& p = a.pooled;
  const std::size_t P = p.phases, Z = p.nz, X = p.nx;
  f.createGroup(L::kFields);
  for (const L::FieldColumn& c : L::kCellFields)
    put(f, L::kFields + "/" + c.name, p.*c.values, {P, Z, X}, c.unit, h5::Storage::compressed);
  for (std::size_t ph = 0; ph < P; ++ph) {
    const std::string grp = fmt::format("{}/p{:04d}", L::kXdmf, ph);
    f.createGroup(grp);
    const int k = static_cast<int>(ph);
    put(f, grp + "/area_fraction", slab(p, p.area_fraction, k), {Z, 1, X}, "1",
        h5::Storage::compressed);
    put(f, grp + "/temperature", slab(p, p.temperature, k), {Z, 1, X}, "J",
        h5::Storage::compressed);
    std::vector<double> v(Z * X * 3, 0.0);
    const auto vx = slab(p, p.velocity_x, k), vz = slab(p, p.velocity_z, k);
    // ParaView's axes: (z, y, x) order of the slab; vector components (x, y, z).
    for (std::size_t c = 0; c < Z * X; ++c) {
      v[3 * c] = vx[c];
      v[3 * c + 2] = vz[c];
    }
    put(f, grp + "/velocity", v, {Z, 1, X, 3}, "m s-1", h5::Storage::compressed);
  }
}

}  // namespace

void writeFieldsFile(const std::string& path, const FieldsAnalysis& a, FieldsCells cells) {
  const PhaseFields& p = a.pooled;
  const FieldGrid& g = a.grid;
  const std::size_t Z = p.nz, X = p.nx;
  h5::AtomicFile af(path);
  h5::File& f = af.file();

  std::vector<double> xs(X), zs(Z);
  for (std::size_t i = 0; i < X; ++i) xs[i] = g.xCentre(static_cast<int>(i));
  for (std::size_t j = 0; j < Z; ++j) zs[j] = g.zCentre(static_cast<int>(j));
  f.createGroup("/grid");
  put(f, L::kGridX, xs, {X}, "m");
  put(f, L::kGridZ, zs, {Z}, "m");
  const bool with_cells = cells == FieldsCells::written;
  f.writeAttribute<std::int64_t>("/", L::kCellsAttribute, with_cells ? 1 : 0);
  if (with_cells) writeCells(f, a);
  writePhaseProfiles(f, "", a.profiles());
  writeStates(f, a);
  writePatterns(f, a.patterns);
  writeSurfaceWaves(f, a.surface);
  writePeriodDoubling(f, a.context.period_doubling);
  writeParameters(f, a);
  af.commit();
  if (!with_cells) return;
  // The pair or neither: a fields file without its sidecar is removed again.
  try {
    writeXdmf(xdmfSidecarPath(path), std::filesystem::path(path).filename().string(), a);
  } catch (...) {
    std::remove(path.c_str());
    throw;
  }
}

}  // namespace granwave
