#include "studies/run_files/HydroRunFile.hpp"

#include <cmath>

#include "h5/AtomicFile.hpp"
#include "h5/File.hpp"

namespace granwave {

namespace {

void put(h5::File& f, const std::string& path, const std::vector<double>& v, const h5::Shape& s,
         const char* unit) {
  f.writeDataset(path, v, s);
  f.writeStringAttribute(path, "unit", unit);
}

void writeFields(h5::File& f, const HydroRunContent& c) {
  const std::size_t P = c.phases, N = c.cells, Z = c.rows;
  f.createGroup("/plate_frame");
  put(f, "/plate_frame/z", c.plate_z, {P, N}, "m");
  put(f, "/plate_frame/number_density", c.number_density, {P, N}, "m-2");
  put(f, "/plate_frame/velocity_z", c.velocity_z, {P, N}, "m s-1");
  put(f, "/plate_frame/temperature", c.temperature, {P, N}, "J");
  put(f, "/plate_frame/area_fraction", c.area_fraction, {P, N}, "1");
  put(f, "/plate_frame/pressure", c.pressure, {P, N}, "N m-1");
  f.createGroup("/lab_frame");
  put(f, "/lab_frame/z", c.lab_z, {Z}, "m");
  put(f, "/lab_frame/area_fraction", c.lab_area_fraction, {P, Z}, "1");
  put(f, "/lab_frame/temperature", c.lab_temperature, {P, Z}, "J");
  put(f, "/lab_frame/velocity_z", c.lab_velocity_z, {P, Z}, "m s-1");
  f.createGroup("/phases");
  put(f, "/phases/time", c.time, {P}, "s");
  put(f, "/phases/plate_height", c.plate_height, {P}, "m");
  put(f, "/phases/center_of_mass_height", c.center_of_mass_height, {P}, "m");
  put(f, "/phases/front_height", c.front_height, {P}, "m");
  put(f, "/phases/front_peak_temperature", c.front_peak_temperature, {P}, "1");
}

void writeFronts(h5::File& f, const std::vector<FrontEpisode>& fronts) {
  std::vector<double> fs, fe, ff, fla, fl, fp;
  for (const auto& e : fronts) {
    fs.push_back(e.speed);
    fe.push_back(e.fit_error);
    ff.push_back(e.first_phase);
    fla.push_back(e.last_phase);
    fl.push_back(e.from_impact ? 1.0 : 0.0);
    fp.push_back(e.peak_temperature);
  }
  f.createGroup("/fronts");
  put(f, "/fronts/speed", fs, {fs.size()}, "m s-1");
  put(f, "/fronts/fit_error", fe, {fe.size()}, "m s-1");
  put(f, "/fronts/first_phase", ff, {ff.size()}, "1");
  put(f, "/fronts/last_phase", fla, {fla.size()}, "1");
  put(f, "/fronts/peak_temperature", fp, {fp.size()}, "1");
  put(f, "/fronts/from_impact", fl, {fl.size()}, "1");
}

void writeSolver(h5::File& f, const HydroRunContent& c) {
  const std::string s = "/solver";
  f.createGroup(s);
  f.writeAttribute<std::int64_t>(s, "cells", static_cast<std::int64_t>(c.cells));
  f.writeAttribute<double>(s, "rtol", c.rtol);
  f.writeAttribute<std::int64_t>(s, "cycles", c.cycles);
  f.writeAttribute<std::int64_t>(s, "period", c.period);
  f.writeAttribute<std::int64_t>(s, "periodic", c.periodic ? 1 : 0);
  f.writeStringAttribute(s, "regime", c.regime);
  f.writeAttribute<double>(s, "cpu_seconds", c.cpu_seconds);
  f.writeAttribute<std::int64_t>(s, "steps", c.steps);
  f.writeAttribute<std::int64_t>(s, "rhs_evals", c.rhs_evals);
  f.writeAttribute<std::int64_t>(s, "jacobian_evals", c.jacobian_evals);
  f.writeAttribute<std::int64_t>(s, "error_test_failures", c.error_test_failures);
  f.writeAttribute<std::int64_t>(s, "nonlinear_failures", c.nonlinear_failures);
}

}  // namespace

void writeHydroRunFile(const std::string& path, const HydroRunContent& c) {
  h5::AtomicFile af(path);
  h5::File& f = af.file();
  f.writeStringAttribute("/", "format", kHydroRunFormat);
  writeFields(f, c);
  writeFronts(f, c.fronts);
  writeSolver(f, c);
  f.createGroup("/parameters");
  f.writeStringDataset("/parameters/scene", c.scene_toml);
  af.commit();
}

HydroFields readHydroFields(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  HydroFields r;
  r.z = f.readDataset<double>("/lab_frame/z");
  r.nz = static_cast<int>(r.z.size());
  const auto time = f.readDataset<double>("/phases/time");
  r.phases = static_cast<int>(time.size());
  r.plate = f.readDataset<double>("/phases/plate_height");
  r.com = f.readDataset<double>("/phases/center_of_mass_height");
  r.temperature = f.readDataset<double>("/lab_frame/temperature");
  r.area_fraction = f.readDataset<double>("/lab_frame/area_fraction");
  r.velocity_z = f.readDataset<double>("/lab_frame/velocity_z");
  r.rms_velocity_x.assign(r.temperature.size(), NAN);
  r.front = f.readDataset<double>("/phases/front_height");
  const std::string s = "/solver";
  r.period = static_cast<int>(f.readAttribute<std::int64_t>(s, "period"));
  r.cycles = static_cast<int>(f.readAttribute<std::int64_t>(s, "cycles"));
  r.cells = static_cast<int>(f.readAttribute<std::int64_t>(s, "cells"));
  r.periodic = f.readAttribute<std::int64_t>(s, "periodic") != 0;
  r.steps = f.readAttribute<std::int64_t>(s, "steps");
  r.rhs_evals = f.readAttribute<std::int64_t>(s, "rhs_evals");
  r.rtol = f.readAttribute<double>(s, "rtol");
  r.cpu_seconds = f.readAttribute<double>(s, "cpu_seconds");
  r.regime = f.readStringAttribute(s, "regime");
  // Phase t/T: the window holds whole cycles sampled at k/M, k = 1..M per cycle.
  // (HydroSimulation keeps 2 cycles when no period was found.)
  const int window_cycles = r.periodic ? r.period : 2;
  for (int p = 0; p < r.phases; ++p)
    r.phase.push_back(static_cast<double>(p + 1) * window_cycles / r.phases);
  const auto speed = f.readDataset<double>("/fronts/speed");
  const auto err = f.readDataset<double>("/fronts/fit_error");
  const auto first = f.readDataset<double>("/fronts/first_phase");
  const auto last = f.readDataset<double>("/fronts/last_phase");
  const auto impact = f.readDataset<double>("/fronts/from_impact");
  const auto peak = f.readDataset<double>("/fronts/peak_temperature");
  for (std::size_t e = 0; e < speed.size(); ++e) {
    Front fr;
    fr.first_phase = static_cast<int>(first[e]);
    fr.last_phase = static_cast<int>(last[e]);
    fr.start = r.phase[static_cast<std::size_t>(first[e])];
    fr.speed = speed[e];
    fr.error = err[e];
    fr.peak = peak[e];
    fr.from_impact = impact[e] > 0.5;
    r.fronts.push_back(fr);
  }
  return r;
}

}  // namespace granwave
