// The fields file read back is what was written: the window's profiles, phases and fronts (of
// the whole run and of each layer state), the parameters, the period-2 series and the
// classification, bit for bit, through the one layout both sides use (FieldsLayout.hpp).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "coarse_grain/FieldsFile.hpp"
#include "coarse_grain/FieldsLayout.hpp"
#include "coarse_grain/FieldsReader.hpp"
#include "tests/h5/ScratchDir.hpp"

namespace granwave {
namespace {

// Equal bit for bit (NaN equals NaN).
bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// Fields of a 4-phase window on a 3 x 3 grid, every value distinct, some cells NaN.
PhaseFields fields(double offset) {
  PhaseFields f;
  f.phases = 4;
  f.nz = 3;
  f.nx = 3;
  int k = 0;
  for (auto* v : {&f.count, &f.area_fraction, &f.velocity_x, &f.velocity_z, &f.temperature,
                  &f.rotational_temperature})
    for (int i = 0; i < 36; ++i) v->push_back(offset + 0.01 * (k++));
  for (auto* v : {&f.profile_temperature, &f.profile_velocity_z, &f.profile_rms_velocity_x,
                  &f.profile_area_fraction})
    for (int i = 0; i < 12; ++i) v->push_back(offset + 0.1 * (k++));
  f.profile_temperature[5] = kNaN;
  f.center_of_mass_height = {offset + 0.001, offset + 0.002, offset + 0.003, offset + 0.004};
  f.snapshots = {10, 10, 10, 10};
  return f;
}

FrontEpisode front(int first, double speed, bool impact) {
  FrontEpisode e;
  e.first_phase = first;
  e.last_phase = (first + 2) % 4;
  e.peak_temperature = 2.5 + speed;
  e.speed = speed;
  e.speed_error = 0.1 * speed;
  e.fit_error = 0.07 * speed;
  e.block_spread = 0.05 * speed;
  e.blocks_used = 2;
  e.gas_velocity_ahead = -0.3;
  e.speed_relative = speed + 0.3;
  e.start_above_plate = 0.001;
  e.from_impact = impact;
  return e;
}

FieldsAnalysis analysis(double offset, int state_period) {
  FieldsAnalysis a;
  a.context = {0.002, 1.2e-5, 1e-11, 10, 0.002, 3.1e-6, 2, {}, "run.h5", "[run]\nseed = 1\n"};
  a.grid = FieldGrid::forContainer(0.006, 0.004, 0.001, 0.002);
  a.samples_per_cycle = 2;
  a.cycles_per_window = 2;
  a.blocks = 2;
  a.discarded_cycles = 6;
  a.pooled_cycles = 20;
  a.pooled = fields(offset);
  a.per_block = {fields(offset + 1), fields(offset + 2)};
  a.front_height = {0.001, kNaN, 0.002, 0.003};
  a.front_peak = {0.6, 0.2, 0.9, 1.4};
  a.fronts = {front(0, 1.5, true), front(2, 0.4, false)};
  a.state_period = state_period;
  return a;
}

FieldsAnalysis fullAnalysis() {
  FieldsAnalysis a = analysis(0, 0);
  PeriodDoublingSeries& pd = a.context.period_doubling;
  pd.f2_strength = {0.05, 0.4, 0.3};
  pd.noise_strength = {0.01, 0.02, 0.2};
  pd.threshold = {0.1, 0.1, 0.6};
  pd.period2 = {0, 1, 0};
  pd.episodes = {{8, 12, 1}, {20, 12, 2}, {32, 12, 1}};
  pd.first_cycle = 8;
  pd.period2_share = 1.0 / 3;
  pd.share_low = 0.06;
  pd.share_high = 0.79;
  pd.effective_windows = 2.5;
  pd.switches = 2;
  a.patterns.available = true;
  a.patterns.state.state = LayerState::crystal;
  a.patterns.state.mean_abs_psi6 = 0.9;
  a.patterns.within_cycle.state = LayerState::liquid_like;
  a.patterns.within_cycle.lid_row = 3.5;
  a.patterns.surface_wave.detected = true;
  a.patterns.surface_wave.mode = 3;
  a.patterns.surface_wave.amplitude_d = 0.7;
  a.patterns.kinks.kink_x = {0.001, 0.004};
  a.state_windows[0] = 1;
  a.state_windows[1] = 4;
  a.states = {analysis(5, 2)};
  return a;
}

void expectSameWindow(const PhaseProfiles& read, const PhaseProfiles& written) {
  EXPECT_TRUE(sameBits(read.z, written.z));
  EXPECT_TRUE(sameBits(read.time, written.time));
  EXPECT_TRUE(sameBits(read.phase, written.phase));
  EXPECT_TRUE(sameBits(read.plate_height, written.plate_height));
  EXPECT_TRUE(sameBits(read.front_height, written.front_height));
  EXPECT_TRUE(sameBits(read.front_peak_temperature, written.front_peak_temperature));
  ASSERT_EQ(read.blocks.size(), written.blocks.size());
  for (std::size_t b = 0; b <= read.blocks.size(); ++b) {
    const PhaseFields& r = b == 0 ? read.pooled : read.blocks[b - 1];
    const PhaseFields& w = b == 0 ? written.pooled : written.blocks[b - 1];
    EXPECT_EQ(r.phases, w.phases);
    EXPECT_EQ(r.nz, w.nz);
    for (const fields_layout::FieldColumn& c : fields_layout::kProfileFields)
      EXPECT_TRUE(sameBits(r.*c.values, w.*c.values)) << "block " << b << " " << c.name;
  }
  EXPECT_TRUE(sameBits(read.pooled.center_of_mass_height, written.pooled.center_of_mass_height));
  ASSERT_EQ(read.fronts.size(), written.fronts.size());
  for (std::size_t e = 0; e < read.fronts.size(); ++e)
    for (const fields_layout::FrontColumn& c : fields_layout::kFrontColumns)
      EXPECT_TRUE(sameBits({c.get(read.fronts[e])}, {c.get(written.fronts[e])}))
          << "front " << e << " " << c.name;
}

}  // namespace

TEST(FieldsFile, ReadsBackTheWindowParametersAndStatesItWrote) {
  testing::ScratchDir dir;
  const FieldsAnalysis a = fullAnalysis();
  writeFieldsFile(dir.file("f.h5"), a);
  const FieldsRecord r = readFieldsFile(dir.file("f.h5"));
  expectSameWindow(r.profiles, a.profiles());
  EXPECT_EQ(r.context.T0, a.context.T0);
  EXPECT_EQ(r.context.frequency, a.context.frequency);
  EXPECT_EQ(r.context.amplitude, a.context.amplitude);
  EXPECT_EQ(r.context.diameter, a.context.diameter);
  EXPECT_EQ(r.context.mass, a.context.mass);
  EXPECT_EQ(r.context.layer_period, 2);
  EXPECT_EQ(r.context.source, "run.h5");
  EXPECT_EQ(r.context.scene_toml, a.context.scene_toml);
  EXPECT_EQ(r.samples_per_cycle, 2);
  EXPECT_EQ(r.cycles_per_window, 2);
  EXPECT_EQ(r.blocks, 2);
  EXPECT_EQ(r.discarded_cycles, 6);
  EXPECT_EQ(r.pooled_cycles, 20);
  EXPECT_EQ(r.state_windows[0], 1);
  EXPECT_EQ(r.state_windows[1], 4);
  EXPECT_EQ(r.profiles.pooled.nx, 3);
}

TEST(FieldsFile, ReadsBackThePeriodTwoSeriesWithItsWindowStates) {
  testing::ScratchDir dir;
  const FieldsAnalysis a = fullAnalysis();
  writeFieldsFile(dir.file("f.h5"), a);
  const PeriodDoublingSeries& w = a.context.period_doubling;
  const PeriodDoublingSeries r = readFieldsFile(dir.file("f.h5")).context.period_doubling;
  EXPECT_TRUE(sameBits(r.f2_strength, w.f2_strength));
  EXPECT_TRUE(sameBits(r.noise_strength, w.noise_strength));
  EXPECT_TRUE(sameBits(r.threshold, w.threshold));
  EXPECT_EQ(r.period2, w.period2);  // strength above threshold, window by window
  EXPECT_EQ(period2Windows(r), 1);
  ASSERT_EQ(r.episodes.size(), 3u);
  EXPECT_EQ(r.episodes[1].first_cycle, 20);
  EXPECT_EQ(r.episodes[1].period, 2);
  EXPECT_EQ(r.first_cycle, 8);
  EXPECT_EQ(r.switches, 2);
  EXPECT_EQ(r.period2_share, w.period2_share);
  EXPECT_EQ(r.share_low, w.share_low);
  EXPECT_EQ(r.share_high, w.share_high);
  EXPECT_EQ(r.effective_windows, w.effective_windows);
}

TEST(FieldsFile, StateFieldsAreThoseOfTheStatesThatWereAveraged) {
  testing::ScratchDir dir;
  const FieldsAnalysis a = fullAnalysis();
  writeFieldsFile(dir.file("f.h5"), a);
  EXPECT_FALSE(readStateFields(dir.file("f.h5"), 1).has_value());
  const std::optional<FieldsRecord> two = readStateFields(dir.file("f.h5"), 2);
  ASSERT_TRUE(two.has_value());
  EXPECT_EQ(two->state_period, 2);
  EXPECT_EQ(two->context.layer_period, 2);
  EXPECT_EQ(two->pooled_cycles, a.states[0].pooled_cycles);
  expectSameWindow(two->profiles, a.states[0].profiles());
}

TEST(FieldsFile, ClassificationIsReadAsStoredLabelsAndCounts) {
  testing::ScratchDir dir;
  writeFieldsFile(dir.file("f.h5"), fullAnalysis());
  const LayerPatterns p = readLayerPatterns(dir.file("f.h5"));
  EXPECT_TRUE(p.available);
  EXPECT_EQ(p.state, "crystal");
  EXPECT_EQ(p.within_cycle_state, "liquid-like");
  EXPECT_TRUE(p.surface_wave);
  EXPECT_EQ(p.surface_wave_mode, 3);
  EXPECT_EQ(p.surface_wave_amplitude_d, 0.7);
  EXPECT_EQ(p.kinks, 2);
  EXPECT_EQ(p.psi6, 0.9);
  EXPECT_EQ(p.lid_row, 3.5);
  EXPECT_EQ(p.period, 2);
}

TEST(FieldsFile, AFileWithoutStatesOrSeriesReadsAsNotMeasured) {
  testing::ScratchDir dir;
  writeFieldsFile(dir.file("f.h5"), analysis(0, 0));
  const FieldsRecord r = readFieldsFile(dir.file("f.h5"));
  EXPECT_EQ(r.state_windows[0], -1);
  EXPECT_EQ(r.state_windows[1], -1);
  EXPECT_TRUE(r.context.period_doubling.f2_strength.empty());
  EXPECT_FALSE(readLayerPatterns(dir.file("f.h5")).available);
  EXPECT_FALSE(readStateFields(dir.file("f.h5"), 2).has_value());
}

}  // namespace granwave
