#include "studies/run_files/HydroRunFile.hpp"

#include <stdexcept>

#include "coarse_grain/FieldsFile.hpp"
#include "coarse_grain/FieldsLayout.hpp"
#include "coarse_grain/FieldsReader.hpp"
#include "h5/AtomicFile.hpp"
#include "h5/File.hpp"

namespace granwave {

namespace {

const std::string kPlateFrame = "/plate_frame";
const std::string kSolver = "/solver";
const std::string kComHistory = "/history/center_of_mass_plate_frame";

void put(h5::File& f, const std::string& path, const std::vector<double>& v, const h5::Shape& s,
         const char* unit) {
  f.writeDataset(path, v, s);
  f.writeStringAttribute(path, "unit", unit);
}

void writePlateFrame(h5::File& f, const HydroRunContent& c) {
  const std::size_t P = c.lab.phases(), N = c.cells;
  const std::string& g = kPlateFrame;
  f.createGroup(g);
  put(f, g + "/z", c.plate_z, {P, N}, "m");
  put(f, g + "/number_density", c.number_density, {P, N}, "m-2");
  put(f, g + "/velocity_z", c.velocity_z, {P, N}, "m s-1");
  put(f, g + "/temperature", c.temperature, {P, N}, "J");
  put(f, g + "/area_fraction", c.area_fraction, {P, N}, "1");
  put(f, g + "/pressure", c.pressure, {P, N}, "N m-1");
}

void writeSolver(h5::File& f, const HydroRunContent& c) {
  const std::string& s = kSolver;
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

void readSolver(const h5::File& f, HydroRunContent& c) {
  const std::string& s = kSolver;
  c.cells = static_cast<std::size_t>(f.readAttribute<std::int64_t>(s, "cells"));
  c.rtol = f.readAttribute<double>(s, "rtol");
  c.cycles = f.readAttribute<std::int64_t>(s, "cycles");
  c.period = f.readAttribute<std::int64_t>(s, "period");
  c.periodic = f.readAttribute<std::int64_t>(s, "periodic") != 0;
  c.regime = f.readStringAttribute(s, "regime");
  c.cpu_seconds = f.readAttribute<double>(s, "cpu_seconds");
  c.steps = f.readAttribute<std::int64_t>(s, "steps");
  c.rhs_evals = f.readAttribute<std::int64_t>(s, "rhs_evals");
  c.jacobian_evals = f.readAttribute<std::int64_t>(s, "jacobian_evals");
  c.error_test_failures = f.readAttribute<std::int64_t>(s, "error_test_failures");
  c.nonlinear_failures = f.readAttribute<std::int64_t>(s, "nonlinear_failures");
}

}  // namespace

void writeHydroRunFile(const std::string& path, const HydroRunContent& c) {
  h5::AtomicFile af(path);
  h5::File& f = af.file();
  f.writeStringAttribute("/", "format", kHydroRunFormat);
  writePlateFrame(f, c);
  f.createGroup("/grid");
  put(f, fields_layout::kGridZ, c.lab.z, {c.lab.z.size()}, "m");
  writePhaseProfiles(f, "", c.lab);
  writeSolver(f, c);
  writeEnergyBudget(f, c.budget);
  if (!c.com_history.empty()) {
    f.createGroup("/history");
    put(f, kComHistory, c.com_history, {c.com_history.size()}, "m");
    f.writeAttribute<std::int64_t>(kComHistory, "phases_per_cycle", c.phases_per_cycle);
  }
  f.createGroup(fields_layout::kParameters);
  f.writeStringDataset(fields_layout::kScene, c.scene_toml);
  af.commit();
}

HydroRunContent readHydroRunFile(const std::string& path) {
  const h5::File f = h5::File::openReadOnly(path);
  // A 2D run file (Hydro2DRunFile.hpp) has another layout: named, not read as garbage.
  if (f.hasAttribute("/", "format") && f.readStringAttribute("/", "format") != kHydroRunFormat)
    throw std::runtime_error(path + ": not a 1D hydro run file (format " +
                             f.readStringAttribute("/", "format") + ", expected " +
                             kHydroRunFormat + ")");
  HydroRunContent c;
  readSolver(f, c);
  c.lab = readPhaseProfiles(f, "");
  c.scene_toml = f.readStringDataset(fields_layout::kScene);
  c.budget = readEnergyBudget(f);
  if (f.isDataset(kComHistory)) {
    c.com_history = f.readDataset<double>(kComHistory);
    c.phases_per_cycle = f.readAttribute<std::int64_t>(kComHistory, "phases_per_cycle");
  }
  // Files without /phases/phase: the window holds whole cycles sampled at k/M, k = 1..M per
  // cycle, as the writer now stores it.
  if (c.lab.phase.empty())
    for (int p = 0; p < c.lab.phases(); ++p)
      c.lab.phase.push_back(static_cast<double>(p + 1) * c.windowCycles() / c.lab.phases());
  return c;
}

}  // namespace granwave
