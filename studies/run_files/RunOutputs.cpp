#include "studies/run_files/RunOutputs.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "h5/File.hpp"
#include "particles/H5mdLayout.hpp"

namespace granwave {

int Profiles::phaseIndex(double t) const {
  // Circular distance: the window repeats (it holds whole cycles of the periodic state).
  const double window = phases > 1 ? phases * (phase[1] - phase[0]) : 1.0;
  auto distance = [&](int p) {
    const double d = std::fmod(std::abs(phase[p] - t), window);
    return std::min(d, window - d);
  };
  int best = 0;
  for (int p = 1; p < phases; ++p)
    if (distance(p) < distance(best)) best = p;
  return best;
}

namespace {
// The profiles and fronts under `root` ("" or /states/periodN) and the run's parameters.
ParticleFields readFieldsUnder(const h5::File& f, const std::string& root) {
  ParticleFields r;
  r.z = f.readDataset<double>("/grid/z");
  r.nz = static_cast<int>(r.z.size());
  r.phase = f.readDataset<double>(root + "/phases/phase");
  r.phases = static_cast<int>(r.phase.size());
  r.plate = f.readDataset<double>(root + "/phases/plate_height");
  r.com = f.readDataset<double>(root + "/phases/center_of_mass_height");
  r.front = f.readDataset<double>(root + "/phases/front_height");
  r.temperature = f.readDataset<double>(root + "/profiles/temperature");
  r.area_fraction = f.readDataset<double>(root + "/profiles/area_fraction");
  r.velocity_z = f.readDataset<double>(root + "/profiles/velocity_z");
  r.rms_velocity_x = f.readDataset<double>(root + "/profiles/rms_velocity_x");
  r.block_temperature = f.readDataset<double>(root + "/blocks/profiles/temperature");
  r.block_area_fraction = f.readDataset<double>(root + "/blocks/profiles/area_fraction");
  r.block_velocity_z = f.readDataset<double>(root + "/blocks/profiles/velocity_z");
  r.block_rms_vx = f.readDataset<double>(root + "/blocks/profiles/rms_velocity_x");
  const std::string par = "/parameters";
  r.T0 = f.readAttribute<double>(par, "T0");
  r.diameter = f.readAttribute<double>(par, "diameter");
  r.mass = f.readAttribute<double>(par, "mass");
  r.frequency = f.readAttribute<double>(par, "frequency");
  r.amplitude = f.readAttribute<double>(par, "amplitude");
  r.cycles_per_window = static_cast<int>(f.readAttribute<std::int64_t>(par, "cycles_per_window"));
  r.layer_period = static_cast<int>(f.readAttribute<std::int64_t>(par, "layer_period"));
  r.pooled_cycles =
      static_cast<int>(f.readAttribute<std::int64_t>(root.empty() ? par : root, "pooled_cycles"));
  r.blocks = static_cast<int>(f.readAttribute<std::int64_t>(par, "blocks"));
  const auto first = f.readDataset<double>(root + "/fronts/first_phase");
  const auto last = f.readDataset<double>(root + "/fronts/last_phase");
  const auto speed = f.readDataset<double>(root + "/fronts/speed");
  const auto error = f.readDataset<double>(root + "/fronts/speed_error");
  const auto peak = f.readDataset<double>(root + "/fronts/peak_temperature");
  const auto gas = f.readDataset<double>(root + "/fronts/gas_velocity_ahead");
  const auto rel = f.readDataset<double>(root + "/fronts/speed_relative");
  const auto impact = f.readDataset<double>(root + "/fronts/from_impact");
  for (std::size_t e = 0; e < speed.size(); ++e) {
    Front fr;
    fr.first_phase = static_cast<int>(first[e]);
    fr.last_phase = static_cast<int>(last[e]);
    fr.start = r.phase[static_cast<std::size_t>(first[e])];
    fr.speed = speed[e];
    fr.error = error[e];
    fr.peak = peak[e];
    fr.gas_ahead = gas[e];
    fr.relative = rel[e];
    fr.from_impact = impact[e] > 0.5;
    r.fronts.push_back(fr);
  }
  return r;
}
}  // namespace

ParticleFields readParticleFields(const std::string& path) {
  return readFieldsUnder(h5::File::openReadOnly(path), "");
}

std::optional<ParticleFields> readStateFields(const std::string& path, int period) {
  const h5::File f = h5::File::openReadOnly(path);
  const std::string root = "/states/period" + std::to_string(period);
  if (!f.isGroup(root)) return std::nullopt;
  ParticleFields r = readFieldsUnder(f, root);
  r.layer_period = period;
  return r;
}

StateSeries readStateSeries(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  StateSeries r;
  if (!f.isGroup("/period_doubling")) return r;
  const std::string g = "/period_doubling";
  r.available = true;
  r.period2_share = f.readAttribute<double>(g, "period2_share");
  r.share_low = f.readAttribute<double>(g, "share_low");
  r.share_high = f.readAttribute<double>(g, "share_high");
  r.window_cycles = static_cast<int>(f.readAttribute<std::int64_t>(g, "window_cycles"));
  r.effective_windows = f.readAttribute<double>(g, "effective_windows");
  r.layer_period = static_cast<int>(f.readAttribute<std::int64_t>("/parameters", "layer_period"));
  r.f2_strength = f.readDataset<double>(g + "/f2_strength");
  if (f.exists(g + "/threshold")) r.threshold = f.readDataset<double>(g + "/threshold");
  for (std::size_t w = 0; w < r.f2_strength.size() && w < r.threshold.size(); ++w)
    r.period2_windows += r.f2_strength[w] > r.threshold[w];
  if (f.isGroup("/states")) {
    r.state_windows[0] =
        static_cast<int>(f.readAttribute<std::int64_t>("/states", "windows_period1"));
    r.state_windows[1] =
        static_cast<int>(f.readAttribute<std::int64_t>("/states", "windows_period2"));
  }
  return r;
}

LammpsTrajectory readLammpsTrajectory(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the LAMMPS output");
  LammpsTrajectory r;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double step = 0, t = 0, zb = 0, com = 0;
    if (!(row >> step >> t >> zb >> com))
      throw std::runtime_error(path + ": malformed line '" + line + "' (expected step t z_b com)");
    r.last_step = step;
    r.time.push_back(t);
    r.plate.push_back(zb);
    r.com.push_back(com);
  }
  return r;
}

LayerPatterns readLayerPatterns(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  LayerPatterns r;
  const std::string g = "/patterns";
  r.period = static_cast<int>(f.readAttribute<std::int64_t>("/parameters", "layer_period"));
  r.available = f.readAttribute<std::int64_t>(g, "available") != 0;
  if (!r.available) return r;
  r.state = f.readStringAttribute(g, "state");
  r.surface_wave = f.readAttribute<std::int64_t>(g, "surface_wave") != 0;
  r.surface_wave_mode = static_cast<int>(f.readAttribute<std::int64_t>(g, "surface_wave_mode"));
  r.surface_wave_amplitude_d = f.readAttribute<double>(g, "surface_wave_amplitude_d");
  r.kinks = static_cast<int>(f.readAttribute<std::int64_t>(g, "kinks"));
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

Frame readLastFrame(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  const std::string pos = h5md::kPosition + "/value";
  const h5::Shape shape = f.shape(pos);  // [frames][N][3]
  Frame fr;
  if (shape.empty() || shape[0] == 0) return fr;
  const std::vector<double> v = f.readRows<double>(pos, shape[0] - 1, 1);
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    fr.x.push_back(v[i]);
    fr.z.push_back(v[i + 2]);
  }
  const auto plate = f.readDataset<double>(h5md::observableGroup("plate_height") + "/value");
  const auto step = f.readDataset<std::int64_t>(h5md::kPosition + "/step");
  const auto obs_step =
      f.readDataset<std::int64_t>(h5md::observableGroup("plate_height") + "/step");
  for (std::size_t i = 0; i < obs_step.size(); ++i)
    if (obs_step[i] == step.back()) fr.plate = plate[i];
  return fr;
}

RunObservables readRunObservables(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  RunObservables r;
  auto series = [&](const std::string& name) {
    return f.readDataset<double>(h5md::observableGroup(name) + "/value");
  };
  r.time = f.readDataset<double>(h5md::observableGroup("center_of_mass_height") + "/time");
  r.com_height = series("center_of_mass_height");
  r.kinetic_energy = series("kinetic_energy");
  r.pair_impact_energy = series("pair_impact_energy");
  r.pair_impact_loss = series("pair_impact_loss");
  const auto events = f.readDataset<std::uint64_t>(h5md::observableGroup("events") + "/value");
  if (!events.empty()) r.events = events.back();
  const auto coll = f.readDataset<std::uint64_t>(h5md::kCollisions + "/value");
  for (std::size_t i = 0; i + 3 < coll.size(); i += 4) {
    r.pair_count.push_back(static_cast<double>(coll[i]));
    r.tc_elastic_count.push_back(static_cast<double>(coll[i + 2]));
  }
  if (coll.size() >= 4) {
    r.pair_collisions = coll[coll.size() - 4];
    r.wall_collisions = coll[coll.size() - 3];
    r.tc_elastic = coll[coll.size() - 2];
  }
  return r;
}

}  // namespace granwave
