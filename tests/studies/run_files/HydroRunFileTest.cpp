// The hydro run file read back is what `granwave hydro` wrote, its lab frame under the fields
// file's names; and a file written before the names were shared (the lab frame under
// /lab_frame, the front's error as fit_error, no /phases/phase) reads to the same values, so
// runs cached by an earlier build stay usable.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "coarse_grain/FieldsLayout.hpp"
#include "h5/File.hpp"
#include "studies/run_files/HydroRunFile.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A period-2 run of 4 phases (2 per cycle) with 3 cells and 5 lab rows.
HydroRunContent content() {
  HydroRunContent c;
  c.cells = 3;
  for (int i = 0; i < 12; ++i) {
    c.plate_z.push_back(1e-3 * i);
    c.number_density.push_back(1e4 + i);
    c.velocity_z.push_back(0.01 * i);
    c.temperature.push_back(1e-7 * i);
    c.area_fraction.push_back(0.05 * i);
    c.pressure.push_back(0.1 * i);
  }
  PhaseProfiles& lab = c.lab;
  lab.pooled.phases = 4;
  lab.pooled.nz = 5;
  lab.pooled.nx = 1;
  lab.z = {-1e-3, 1e-3, 3e-3, 5e-3, 7e-3};
  lab.time = {0.05, 0.1, 0.15, 0.2};
  lab.phase = {0.5, 1.0, 1.5, 2.0};
  lab.plate_height = {1e-3, 0.0, -1e-3, 0.0};
  lab.front_height = {2e-3, NAN, 4e-3, 5e-3};
  lab.front_peak_temperature = {0.7, 0.1, 0.8, 0.9};
  for (int i = 0; i < 20; ++i) {
    lab.pooled.profile_area_fraction.push_back(i < 10 ? 0.5 : 0.0);
    lab.pooled.profile_temperature.push_back(i < 10 ? 1e-6 * i : NAN);
    lab.pooled.profile_velocity_z.push_back(i < 10 ? 0.1 * i : NAN);
  }
  lab.pooled.center_of_mass_height = {3e-3, 3.1e-3, 3.2e-3, 3.3e-3};
  FrontEpisode e;
  e.first_phase = 2;
  e.last_phase = 0;
  e.speed = 1.7;
  e.speed_error = e.fit_error = 0.12;
  e.gas_velocity_ahead = -0.4;
  e.speed_relative = 2.1;
  e.peak_temperature = 0.8;
  e.start_above_plate = 5e-3;
  lab.fronts = {e};
  c.rtol = 1e-4;
  c.cycles = 12;
  c.period = 2;
  c.periodic = true;
  c.steps = 1500;
  c.rhs_evals = 3000;
  c.jacobian_evals = 40;
  c.error_test_failures = 3;
  c.nonlinear_failures = 1;
  c.regime = "fluidised";
  c.cpu_seconds = 0.25;
  c.scene_toml = "[hydro]\ncells = 3\n";
  return c;
}

void put(h5::File& f, const std::string& path, const std::vector<double>& v, h5::Shape shape) {
  f.writeDataset(path, v, shape);
}

// The file as builds before the shared names wrote it.
void writeEarlierLayout(const std::string& path, const HydroRunContent& c) {
  h5::File f = h5::File::create(path);
  const PhaseProfiles& lab = c.lab;
  f.createGroup("/lab_frame");
  put(f, "/lab_frame/z", lab.z, {5});
  put(f, "/lab_frame/area_fraction", lab.pooled.profile_area_fraction, {4, 5});
  put(f, "/lab_frame/temperature", lab.pooled.profile_temperature, {4, 5});
  put(f, "/lab_frame/velocity_z", lab.pooled.profile_velocity_z, {4, 5});
  f.createGroup("/phases");
  put(f, "/phases/time", lab.time, {4});
  put(f, "/phases/plate_height", lab.plate_height, {4});
  put(f, "/phases/center_of_mass_height", lab.pooled.center_of_mass_height, {4});
  put(f, "/phases/front_height", lab.front_height, {4});
  put(f, "/phases/front_peak_temperature", lab.front_peak_temperature, {4});
  const FrontEpisode& e = lab.fronts[0];
  f.createGroup("/fronts");
  put(f, "/fronts/speed", {e.speed}, {1});
  put(f, "/fronts/fit_error", {e.speed_error}, {1});
  put(f, "/fronts/first_phase", {2.0}, {1});
  put(f, "/fronts/last_phase", {0.0}, {1});
  put(f, "/fronts/peak_temperature", {e.peak_temperature}, {1});
  put(f, "/fronts/from_impact", {1.0}, {1});
  f.createGroup("/solver");
  for (const char* a : {"cells", "cycles", "period", "periodic", "steps", "rhs_evals",
                        "jacobian_evals", "error_test_failures", "nonlinear_failures"})
    f.writeAttribute<std::int64_t>("/solver", a, 1);
  f.writeAttribute<std::int64_t>("/solver", "period", c.period);
  f.writeAttribute<double>("/solver", "rtol", c.rtol);
  f.writeAttribute<double>("/solver", "cpu_seconds", c.cpu_seconds);
  f.writeStringAttribute("/solver", "regime", c.regime);
  f.createGroup("/parameters");
  f.writeStringDataset("/parameters/scene", c.scene_toml);
  f.close();
}

void expectSameLab(const PhaseProfiles& r, const PhaseProfiles& w) {
  EXPECT_TRUE(sameBits(r.z, w.z));
  EXPECT_TRUE(sameBits(r.time, w.time));
  EXPECT_TRUE(sameBits(r.phase, w.phase));
  EXPECT_TRUE(sameBits(r.plate_height, w.plate_height));
  EXPECT_TRUE(sameBits(r.front_height, w.front_height));
  EXPECT_TRUE(sameBits(r.front_peak_temperature, w.front_peak_temperature));
  EXPECT_TRUE(sameBits(r.pooled.center_of_mass_height, w.pooled.center_of_mass_height));
  EXPECT_TRUE(sameBits(r.pooled.profile_area_fraction, w.pooled.profile_area_fraction));
  EXPECT_TRUE(sameBits(r.pooled.profile_temperature, w.pooled.profile_temperature));
  EXPECT_TRUE(sameBits(r.pooled.profile_velocity_z, w.pooled.profile_velocity_z));
  // The continuum has no RMS(v_x): not in the file, NaN when read.
  ASSERT_EQ(r.pooled.profile_rms_velocity_x.size(), 20u);
  EXPECT_TRUE(std::isnan(r.pooled.profile_rms_velocity_x[7]));
  EXPECT_TRUE(r.blocks.empty());
  ASSERT_EQ(r.fronts.size(), 1u);
  EXPECT_EQ(r.fronts[0].first_phase, 2);
  EXPECT_EQ(r.fronts[0].last_phase, 0);
  EXPECT_EQ(r.fronts[0].speed, 1.7);
  EXPECT_EQ(r.fronts[0].speed_error, 0.12);
  EXPECT_EQ(r.fronts[0].peak_temperature, 0.8);
  EXPECT_TRUE(r.fronts[0].from_impact);
  EXPECT_EQ(r.start(r.fronts[0]), 1.5);
}

}  // namespace

TEST(HydroRunFile, ReadsBackTheLabFrameFrontsAndSolverItWrote) {
  testing::ScratchDir dir;
  const HydroRunContent c = content();
  writeHydroRunFile(dir.file("h.h5"), c);
  const HydroRunContent r = readHydroRunFile(dir.file("h.h5"));
  expectSameLab(r.lab, c.lab);
  EXPECT_EQ(r.lab.fronts[0].gas_velocity_ahead, -0.4);
  EXPECT_EQ(r.lab.fronts[0].speed_relative, 2.1);
  EXPECT_EQ(r.lab.fronts[0].start_above_plate, 5e-3);
  EXPECT_EQ(r.cells, 3u);
  EXPECT_EQ(r.period, 2);
  EXPECT_TRUE(r.periodic);
  EXPECT_EQ(r.windowCycles(), 2);
  EXPECT_EQ(r.cycles, 12);
  EXPECT_EQ(r.steps, 1500);
  EXPECT_EQ(r.rhs_evals, 3000);
  EXPECT_EQ(r.rtol, 1e-4);
  EXPECT_EQ(r.cpu_seconds, 0.25);
  EXPECT_EQ(r.regime, "fluidised");
  EXPECT_EQ(r.scene_toml, c.scene_toml);
}

TEST(HydroRunFile, NamesEachQuantityAsTheFieldsFileDoes) {
  testing::ScratchDir dir;
  writeHydroRunFile(dir.file("h.h5"), content());
  const h5::File f = h5::File::openReadOnly(dir.file("h.h5"));
  namespace L = fields_layout;
  EXPECT_TRUE(f.isDataset(L::kGridZ));
  EXPECT_TRUE(f.isDataset(L::kProfiles + "/temperature"));
  EXPECT_TRUE(f.isDataset(L::kPhases + "/" + L::kPhase));
  for (const L::FrontColumn& c : L::kFrontColumns)
    EXPECT_TRUE(f.isDataset(L::kFronts + "/" + c.name)) << c.name;
  EXPECT_FALSE(f.exists(L::kEarlierLabFrame));
  EXPECT_FALSE(f.exists(L::kProfiles + "/rms_velocity_x"));
  EXPECT_EQ(f.shape("/plate_frame/temperature"), (h5::Shape{4, 3}));
}

TEST(HydroRunFile, AFileWithTheEarlierNamesReadsToTheSameValues) {
  testing::ScratchDir dir;
  const HydroRunContent c = content();
  writeEarlierLayout(dir.file("old.h5"), c);
  const HydroRunContent r = readHydroRunFile(dir.file("old.h5"));
  // The phases, which those files did not store, from the window: (k + 1) / M per cycle.
  expectSameLab(r.lab, c.lab);
  EXPECT_EQ(r.period, 2);
  EXPECT_EQ(r.regime, "fluidised");
}

}  // namespace granwave
