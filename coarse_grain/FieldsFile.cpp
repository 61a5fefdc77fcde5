#include "coarse_grain/FieldsFile.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "coarse_grain/SurfaceWavesFile.hpp"
#include "files/OutputPath.hpp"
#include "h5/AtomicFile.hpp"

namespace granwave {

namespace {

using Shape = h5::Shape;

void put(h5::File& f, const std::string& path, const std::vector<double>& v, const Shape& shape,
         const char* unit) {
  f.writeDataset(path, v, shape);
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
  f.createGroup("/patterns");
  const std::string g = "/patterns";
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
  const std::string g = "/period_doubling";
  f.createGroup(g);
  put(f, g + "/f2_strength", pd.f2_strength, {pd.f2_strength.size()}, "1");
  put(f, g + "/noise_strength", pd.noise_strength, {pd.noise_strength.size()}, "1");
  put(f, g + "/threshold", pd.threshold, {pd.threshold.size()}, "1");
  std::vector<std::int64_t> episodes;
  for (const StateEpisode& e : pd.episodes)
    episodes.insert(episodes.end(), {e.first_cycle, e.cycles, e.period});
  f.writeDataset(g + "/episodes", episodes, {pd.episodes.size(), 3});
  f.writeStringAttribute(g + "/episodes", "unit", "1");  // cycles, cycles, period (counts)
  f.writeAttribute<std::int64_t>(g, "window_cycles", pd.window_cycles);
  f.writeAttribute<std::int64_t>(g, "first_cycle", pd.first_cycle);
  f.writeAttribute<double>(g, "period2_share", pd.period2_share);
  f.writeAttribute<double>(g, "share_low", pd.share_low);
  f.writeAttribute<double>(g, "share_high", pd.share_high);
  f.writeAttribute<double>(g, "effective_windows", pd.effective_windows);
  f.writeAttribute<std::int64_t>(g, "switches", pd.switches);
}

// Profiles, per-block profiles, phases and fronts of `a` under `root` ("" for the whole run;
// readParticleFields reads the same layout).
void writeProfilesAndFronts(h5::File& f, const std::string& root, const FieldsAnalysis& a) {
  const PhaseFields& p = a.pooled;
  const std::size_t P = p.phases, Z = p.nz, B = a.per_block.size();
  f.createGroup(root + "/profiles");
  put(f, root + "/profiles/temperature", p.profile_temperature, {P, Z}, "J");
  put(f, root + "/profiles/velocity_z", p.profile_velocity_z, {P, Z}, "m s-1");
  put(f, root + "/profiles/rms_velocity_x", p.profile_rms_velocity_x, {P, Z}, "m s-1");
  put(f, root + "/profiles/area_fraction", p.profile_area_fraction, {P, Z}, "1");

  f.createGroup(root + "/blocks/profiles");
  auto stack = [&](auto member) {
    std::vector<double> v;
    for (const PhaseFields& b : a.per_block)
      v.insert(v.end(), (b.*member).begin(), (b.*member).end());
    return v;
  };
  put(f, root + "/blocks/profiles/temperature", stack(&PhaseFields::profile_temperature), {B, P, Z},
      "J");
  put(f, root + "/blocks/profiles/velocity_z", stack(&PhaseFields::profile_velocity_z), {B, P, Z},
      "m s-1");
  put(f, root + "/blocks/profiles/rms_velocity_x", stack(&PhaseFields::profile_rms_velocity_x),
      {B, P, Z}, "m s-1");
  put(f, root + "/blocks/profiles/area_fraction", stack(&PhaseFields::profile_area_fraction),
      {B, P, Z}, "1");

  std::vector<double> time(P), phase(P), plate(P);
  for (std::size_t k = 0; k < P; ++k) {
    time[k] = a.phaseTime(static_cast<int>(k));
    phase[k] = static_cast<double>(k) / a.samples_per_cycle;
    plate[k] = a.plateHeight(static_cast<int>(k));
  }
  f.createGroup(root + "/phases");
  put(f, root + "/phases/time", time, {P}, "s");
  put(f, root + "/phases/phase", phase, {P}, "1");  // t/T, 0 .. cycles_per_window
  put(f, root + "/phases/plate_height", plate, {P}, "m");
  put(f, root + "/phases/center_of_mass_height", p.center_of_mass_height, {P}, "m");
  put(f, root + "/phases/front_height", a.front_height, {P}, "m");
  put(f, root + "/phases/front_peak_temperature", a.front_peak, {P}, "1");  // T~_g / T0

  f.createGroup(root + "/fronts");
  const std::size_t E = a.fronts.size();
  auto column = [&](auto get) {
    std::vector<double> v;
    for (const FrontEpisode& e : a.fronts) v.push_back(get(e));
    return v;
  };
  put(f, root + "/fronts/first_phase", column([](auto& e) { return double(e.first_phase); }), {E},
      "1");
  put(f, root + "/fronts/last_phase", column([](auto& e) { return double(e.last_phase); }), {E},
      "1");
  put(f, root + "/fronts/speed", column([](auto& e) { return e.speed; }), {E}, "m s-1");
  put(f, root + "/fronts/speed_error", column([](auto& e) { return e.speed_error; }), {E}, "m s-1");
  put(f, root + "/fronts/fit_error", column([](auto& e) { return e.fit_error; }), {E}, "m s-1");
  put(f, root + "/fronts/block_spread", column([](auto& e) { return e.block_spread; }), {E},
      "m s-1");
  put(f, root + "/fronts/blocks_used", column([](auto& e) { return double(e.blocks_used); }), {E},
      "1");
  put(f, root + "/fronts/gas_velocity_ahead", column([](auto& e) { return e.gas_velocity_ahead; }),
      {E}, "m s-1");
  put(f, root + "/fronts/speed_relative", column([](auto& e) { return e.speed_relative; }), {E},
      "m s-1");
  put(f, root + "/fronts/peak_temperature", column([](auto& e) { return e.peak_temperature; }), {E},
      "1");
  put(f, root + "/fronts/start_above_plate", column([](auto& e) { return e.start_above_plate; }),
      {E}, "m");
  put(f, root + "/fronts/from_impact", column([](auto& e) { return e.from_impact ? 1.0 : 0.0; }),
      {E}, "1");
}

// The fields conditioned on the layer's state (/states/period1, /states/period2; attributes
// windows and pooled_cycles); /states has windows_period1 and windows_period2 (-1: not measured).
void writeStates(h5::File& f, const FieldsAnalysis& a) {
  if (a.state_windows[0] < 0) return;
  f.createGroup("/states");
  f.writeAttribute<std::int64_t>("/states", "windows_period1", a.state_windows[0]);
  f.writeAttribute<std::int64_t>("/states", "windows_period2", a.state_windows[1]);
  for (const FieldsAnalysis& s : a.states) {
    const std::string root = fmt::format("/states/period{}", s.state_period);
    f.createGroup(root);
    writeProfilesAndFronts(f, root, s);
    f.writeAttribute<std::int64_t>(root, "windows", a.state_windows[s.state_period - 1]);
    f.writeAttribute<std::int64_t>(root, "pooled_cycles", s.pooled_cycles);
  }
}

}  // namespace

std::string xdmfSidecarPath(const std::string& fields_path) {
  std::filesystem::path p(fields_path);
  p.replace_extension(".xdmf");
  return p.string();
}

void writeFieldsFile(const std::string& path, const FieldsAnalysis& a) {
  const PhaseFields& p = a.pooled;
  const FieldGrid& g = a.grid;
  const std::size_t P = p.phases, Z = p.nz, X = p.nx;
  h5::AtomicFile af(path);
  h5::File& f = af.file();

  std::vector<double> xs(X), zs(Z);
  for (std::size_t i = 0; i < X; ++i) xs[i] = g.xCentre(static_cast<int>(i));
  for (std::size_t j = 0; j < Z; ++j) zs[j] = g.zCentre(static_cast<int>(j));
  f.createGroup("/grid");
  put(f, "/grid/x", xs, {X}, "m");
  put(f, "/grid/z", zs, {Z}, "m");

  f.createGroup("/fields");
  put(f, "/fields/count", p.count, {P, Z, X}, "1");
  put(f, "/fields/area_fraction", p.area_fraction, {P, Z, X}, "1");
  put(f, "/fields/velocity_x", p.velocity_x, {P, Z, X}, "m s-1");
  put(f, "/fields/velocity_z", p.velocity_z, {P, Z, X}, "m s-1");
  put(f, "/fields/temperature", p.temperature, {P, Z, X}, "J");
  put(f, "/fields/rotational_temperature", p.rotational_temperature, {P, Z, X}, "J");

  writeProfilesAndFronts(f, "", a);
  writeStates(f, a);

  for (std::size_t ph = 0; ph < P; ++ph) {
    const std::string grp = fmt::format("/xdmf/p{:04d}", ph);
    f.createGroup(grp);
    const int k = static_cast<int>(ph);
    put(f, grp + "/area_fraction", slab(p, p.area_fraction, k), {Z, 1, X}, "1");
    put(f, grp + "/temperature", slab(p, p.temperature, k), {Z, 1, X}, "J");
    std::vector<double> v(Z * X * 3, 0.0);
    const auto vx = slab(p, p.velocity_x, k), vz = slab(p, p.velocity_z, k);
    // ParaView's axes: (z, y, x) order of the slab; vector components (x, y, z).
    for (std::size_t c = 0; c < Z * X; ++c) {
      v[3 * c] = vx[c];
      v[3 * c + 2] = vz[c];
    }
    put(f, grp + "/velocity", v, {Z, 1, X, 3}, "m s-1");
  }

  writePatterns(f, a.patterns);
  writeSurfaceWaves(f, a.surface);
  writePeriodDoubling(f, a.context.period_doubling);

  f.createGroup("/parameters");
  const std::string par = "/parameters";
  f.writeStringAttribute(par, "format", kFieldsFormat);
  f.writeStringAttribute(par, "source", a.context.source);
  f.writeAttribute<double>(par, "diameter", a.context.diameter);
  f.writeAttribute<double>(par, "mass", a.context.mass);
  f.writeAttribute<double>(par, "frequency", a.context.frequency);
  f.writeAttribute<double>(par, "amplitude", a.context.amplitude);
  f.writeAttribute<double>(par, "T0", a.context.T0);
  f.writeAttribute<std::int64_t>(par, "samples_per_cycle", a.samples_per_cycle);
  f.writeAttribute<std::int64_t>(par, "cycles_per_window", a.cycles_per_window);
  f.writeAttribute<std::int64_t>(par, "blocks", a.blocks);
  f.writeAttribute<std::int64_t>(par, "discarded_cycles", a.discarded_cycles);
  f.writeAttribute<std::int64_t>(par, "pooled_cycles", a.pooled_cycles);
  f.writeAttribute<std::int64_t>(par, "layer_period", a.context.layer_period);
  f.writeAttribute<std::int64_t>(par, "min_count", a.params.min_count);
  f.writeAttribute<double>(par, "front_threshold", a.front_options.threshold);
  f.writeAttribute<double>(par, "front_layer_min_area_fraction",
                           a.front_options.layer_min_area_fraction);
  f.writeStringDataset("/parameters/scene", a.context.scene_toml);
  af.commit();
  // The pair or neither: a fields file without its sidecar is removed again.
  try {
    writeXdmf(xdmfSidecarPath(path), std::filesystem::path(path).filename().string(), a);
  } catch (...) {
    std::remove(path.c_str());
    throw;
  }
}

}  // namespace granwave
