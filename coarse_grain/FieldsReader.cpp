#include "coarse_grain/FieldsReader.hpp"

#include "coarse_grain/FieldsLayout.hpp"

namespace granwave {

namespace {

namespace L = fields_layout;

int integer(const h5::File& f, const std::string& object, const char* name) {
  return static_cast<int>(f.readAttribute<std::int64_t>(object, name));
}

// `path`, or the same under the name hydro run files used before (`earlier`), or empty.
std::vector<double> readEither(const h5::File& f, const std::string& path,
                               const std::string& earlier) {
  if (f.exists(path)) return f.readDataset<double>(path);
  if (!earlier.empty() && f.exists(earlier)) return f.readDataset<double>(earlier);
  return {};
}

// [block][phase][z] per profile, split into one PhaseFields per block.
std::vector<PhaseFields> readBlocks(const h5::File& f, const std::string& root,
                                    const PhaseFields& pooled) {
  std::vector<PhaseFields> blocks;
  const std::string g = root + L::kBlockProfiles;
  if (!f.isGroup(g)) return blocks;
  const std::size_t n = static_cast<std::size_t>(pooled.phases) * pooled.nz;
  PhaseFields shape;
  shape.phases = pooled.phases;
  shape.nz = pooled.nz;
  shape.nx = pooled.nx;
  for (const L::FieldColumn& c : L::kProfileFields) {
    const std::vector<double> stacked = f.readDataset<double>(g + "/" + c.name);
    blocks.resize(n > 0 ? stacked.size() / n : 0, shape);
    for (std::size_t b = 0; b < blocks.size(); ++b)
      (blocks[b].*c.values)
          .assign(stacked.begin() + static_cast<long>(b * n),
                  stacked.begin() + static_cast<long>((b + 1) * n));
  }
  return blocks;
}

std::vector<FrontEpisode> readFronts(const h5::File& f, const std::string& root) {
  const std::string g = root + L::kFronts + "/";
  std::vector<FrontEpisode> fronts(f.shape(g + L::kFrontColumns[0].name).at(0));
  for (const L::FrontColumn& c : L::kFrontColumns) {
    const std::vector<double> column =
        readEither(f, g + c.name, c.earlier_name ? g + c.earlier_name : "");
    for (std::size_t e = 0; e < column.size() && e < fronts.size(); ++e)
      c.set(fronts[e], column[e]);
  }
  return fronts;
}

PeriodDoublingSeries readPeriodDoubling(const h5::File& f) {
  PeriodDoublingSeries pd;
  const std::string& g = L::kPeriodDoubling;
  if (!f.isGroup(g)) return pd;
  pd.f2_strength = f.readDataset<double>(g + "/" + L::kF2Strength);
  pd.noise_strength = readEither(f, g + "/" + L::kNoiseStrength, "");
  pd.threshold = readEither(f, g + "/" + L::kThreshold, "");
  for (std::size_t w = 0; w < pd.f2_strength.size() && w < pd.threshold.size(); ++w)
    pd.period2.push_back(pd.f2_strength[w] > pd.threshold[w] ? 1 : 0);
  if (f.exists(g + "/" + L::kEpisodes)) {
    const auto rows = f.readDataset<std::int64_t>(g + "/" + L::kEpisodes);
    for (std::size_t i = 0; i + 2 < rows.size(); i += 3)
      pd.episodes.push_back({static_cast<int>(rows[i]), static_cast<int>(rows[i + 1]),
                             static_cast<int>(rows[i + 2])});
  }
  pd.window_cycles = integer(f, g, "window_cycles");
  pd.period2_share = f.readAttribute<double>(g, "period2_share");
  pd.share_low = f.readAttribute<double>(g, "share_low");
  pd.share_high = f.readAttribute<double>(g, "share_high");
  pd.effective_windows = f.readAttribute<double>(g, "effective_windows");
  if (f.hasAttribute(g, "first_cycle")) pd.first_cycle = integer(f, g, "first_cycle");
  if (f.hasAttribute(g, "switches")) pd.switches = integer(f, g, "switches");
  return pd;
}

// The parameters and the window under `root`.
FieldsRecord readRecord(const h5::File& f, const std::string& root) {
  FieldsRecord r;
  const std::string& par = L::kParameters;
  FieldsContext& c = r.context;
  c.source = f.readStringAttribute(par, L::kSource);
  c.diameter = f.readAttribute<double>(par, L::kDiameter);
  c.mass = f.readAttribute<double>(par, L::kMass);
  c.frequency = f.readAttribute<double>(par, L::kFrequency);
  c.amplitude = f.readAttribute<double>(par, L::kAmplitude);
  c.T0 = f.readAttribute<double>(par, L::kT0);
  c.layer_period = integer(f, par, L::kLayerPeriod);
  c.scene_toml = f.readStringDataset(L::kScene);
  r.samples_per_cycle = integer(f, par, L::kSamplesPerCycle);
  r.cycles_per_window = integer(f, par, L::kCyclesPerWindow);
  r.blocks = integer(f, par, L::kBlocks);
  r.discarded_cycles = integer(f, par, L::kDiscardedCycles);
  r.pooled_cycles = integer(f, root.empty() ? par : root, L::kPooledCycles);
  r.profiles = readPhaseProfiles(f, root);
  return r;
}

}  // namespace

PhaseProfiles readPhaseProfiles(const h5::File& f, const std::string& root) {
  PhaseProfiles p;
  const std::string earlier = root.empty() ? L::kEarlierLabFrame + "/" : "";
  p.z = readEither(f, L::kGridZ, earlier.empty() ? "" : earlier + "z");
  const std::string phases = root + L::kPhases + "/";
  p.time = f.readDataset<double>(phases + L::kTime);
  p.phase = readEither(f, phases + L::kPhase, "");
  p.plate_height = f.readDataset<double>(phases + L::kPlateHeight);
  p.front_height = f.readDataset<double>(phases + L::kFrontHeight);
  p.front_peak_temperature = f.readDataset<double>(phases + L::kFrontPeak);
  p.pooled.phases = static_cast<int>(p.time.size());
  p.pooled.nz = static_cast<int>(p.z.size());
  p.pooled.nx = f.exists(L::kGridX) ? static_cast<int>(f.shape(L::kGridX).at(0)) : 1;
  p.pooled.center_of_mass_height = f.readDataset<double>(phases + L::kCenterOfMass);
  for (const L::FieldColumn& c : L::kBudgetSeries)  // absent in files written before them
    if (f.exists(phases + c.name)) p.pooled.*c.values = f.readDataset<double>(phases + c.name);
  const std::size_t n = static_cast<std::size_t>(p.pooled.phases) * p.pooled.nz;
  for (const L::FieldColumn& c : L::kProfileFields) {
    std::vector<double>& v = p.pooled.*c.values;
    v = readEither(f, root + L::kProfiles + "/" + c.name, earlier.empty() ? "" : earlier + c.name);
    if (v.empty()) v.assign(n, kNaN);  // not measured by this model (the continuum's RMS(v_x))
  }
  p.blocks = readBlocks(f, root, p.pooled);
  p.fronts = readFronts(f, root);
  return p;
}

FieldsRecord readFieldsFile(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  FieldsRecord r = readRecord(f, "");
  r.context.period_doubling = readPeriodDoubling(f);
  if (f.isGroup(L::kStates))
    for (int k = 0; k < 2; ++k)
      r.state_windows[k] = integer(f, L::kStates, L::kStateWindows[k].c_str());
  return r;
}

std::optional<FieldsRecord> readStateFields(const std::string& path, int period) {
  const h5::File f = h5::File::openReadOnly(path);
  const std::string root = L::stateRoot(period);
  if (!f.isGroup(root)) return std::nullopt;
  FieldsRecord r = readRecord(f, root);
  r.state_period = period;
  r.context.layer_period = period;
  return r;
}

LayerPatterns readLayerPatterns(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  LayerPatterns r;
  const std::string& g = L::kPatterns;
  r.period = integer(f, L::kParameters, L::kLayerPeriod);
  r.available = f.readAttribute<std::int64_t>(g, "available") != 0;
  if (!r.available) return r;
  r.state = f.readStringAttribute(g, "state");
  r.surface_wave = f.readAttribute<std::int64_t>(g, "surface_wave") != 0;
  r.surface_wave_mode = integer(f, g, "surface_wave_mode");
  r.surface_wave_amplitude_d = f.readAttribute<double>(g, "surface_wave_amplitude_d");
  r.kinks = integer(f, g, "kinks");
  r.psi6 = f.readAttribute<double>(g, "mean_abs_psi6");
  r.mobility_d = f.readAttribute<double>(g, "mean_relative_displacement_d");
  r.bonds_kept = f.readAttribute<double>(g, "bonds_kept");
  r.bonds_kept_per_cycle = f.readAttribute<double>(g, "bonds_kept_per_cycle");
  r.within_cycle_state = f.readStringAttribute(g, "within_cycle_state");
  r.within_cycle_coordination = f.readAttribute<double>(g, "within_cycle_coordination");
  r.within_cycle_psi6 = f.readAttribute<double>(g, "within_cycle_psi6");
  r.lid_row = f.readAttribute<double>(g, "lid_row");
  return r;
}

}  // namespace granwave
