#include "studies/readings/ReadingsStudy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "scene/SceneDerived.hpp"
#include "studies/readings/ReadingsAnalysis.hpp"
#include "studies/readings/ReadingsReport.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

std::vector<std::string> Reading::overrides() const {
  return {"contact.kappa_units=" + kappa_units, "contact.wall_tangential=" + wall_tangential,
          "contact.tc_tangential=" + tc_tangential, "contact.tc_window=" + tc_window};
}

std::vector<DrivePoint> ReadingsConfig::points() const {
  std::vector<DrivePoint> p;
  for (double g : gammas) p.push_back({frequency, g});
  for (double f : high_frequencies) p.push_back({f, high_gamma});
  return p;
}

int ReadingsConfig::wavePoint() const {
  const auto it = std::find(gammas.begin(), gammas.end(), wave_gamma);
  return static_cast<int>(it - gammas.begin());
}

std::string ReadingsConfig::run(int reading, int law, const DrivePoint& p, int seed) const {
  return particleLabel(law, fmt::format("[{}] f={} Gamma={} seed {}", readings[reading].name,
                                        formatCompact(p.frequency), formatCompact(p.gamma), seed));
}

namespace {

// The readings of the shipped study file when [readings] is absent: today's model, the
// alternatives most likely to matter first (kappa in cm/s; e_t = +1 in TC collisions alone,
// with the walls, and with every alternative), then the others (docs/studies.md).
std::vector<Reading> defaultReadings() {
  return {{"as built", "si", "smooth", "smooth", "rolling"},
          {"kappa cm/s", "cgs", "smooth", "smooth", "rolling"},
          {"rough-elastic TC", "si", "smooth", "rough-elastic", "rolling"},
          {"e_t=+1 walls and TC", "si", "rough-elastic", "rough-elastic", "rolling"},
          {"cm/s, e_t=+1, anchored", "cgs", "rough-elastic", "rough-elastic", "anchored"},
          {"anchored TC", "si", "smooth", "smooth", "anchored"},
          {"kappa v/sqrt(gd)", "gd", "smooth", "smooth", "rolling"},
          {"rough-elastic walls", "si", "rough-elastic", "smooth", "rolling"}};
}

}  // namespace

void ReadingsStudy::readReadings(StudyFile& f) {
  const std::vector<Reading> d = defaultReadings();
  auto column = [&](const char* key, std::string Reading::*member) {
    std::vector<std::string> v;
    for (const Reading& r : d) v.push_back(r.*member);
    return f.strings("readings", key, v);
  };
  const auto names = column("names", &Reading::name);
  const auto kappa = column("kappa_units", &Reading::kappa_units);
  const auto wall = column("wall_tangential", &Reading::wall_tangential);
  const auto tc = column("tc_tangential", &Reading::tc_tangential);
  const auto window = column("tc_window", &Reading::tc_window);
  for (const auto* v : {&kappa, &wall, &tc, &window})
    if (v->size() != names.size())
      f.fail("readings", "names",
             fmt::format("expected kappa_units, wall_tangential, tc_tangential and tc_window "
                         "with one value per name ({} names)",
                         names.size()));
  if (names.empty()) f.fail("readings", "names", "expected at least one reading");
  if (std::set<std::string>(names.begin(), names.end()).size() != names.size())
    f.fail("readings", "names", "expected distinct names");
  for (std::size_t i = 0; i < names.size(); ++i)
    c_.readings.push_back({names[i], kappa[i], wall[i], tc[i], window[i]});
}

void ReadingsStudy::readKeys(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  readReadings(f);
  c_.frequency = f.number("checks", "frequency", c_.frequency);
  c_.gammas = f.numbers("checks", "gammas", c_.gammas);
  c_.wave_gamma = f.number("checks", "wave_gamma", c_.wave_gamma);
  c_.high_frequencies = f.numbers("checks", "high_frequencies", c_.high_frequencies);
  c_.high_gamma = f.number("checks", "high_gamma", c_.high_gamma);
  c_.cycles = f.number("particles", "cycles", c_.cycles);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.wave_duration = f.number("momentum", "wave_duration", c_.wave_duration);
  c_.min_rms = f.number("momentum", "min_rms", c_.min_rms);
  c_.min_area_fraction = f.number("momentum", "min_area_fraction", c_.min_area_fraction);
  if (!(c_.frequency > 0)) f.fail("checks", "frequency", "expected a frequency > 0 in Hz");
  if (c_.high_frequencies.empty()) f.fail("checks", "high_frequencies", "expected at least one");
  for (std::size_t i = 0; i < c_.high_frequencies.size(); ++i)
    if (!(c_.high_frequencies[i] > (i ? c_.high_frequencies[i - 1] : c_.frequency)))
      f.fail("checks", "high_frequencies",
             "expected rising frequencies above [checks] frequency (Hz)");
  if (!(c_.high_gamma > 1)) f.fail("checks", "high_gamma", "expected Gamma > 1");
  for (double g : c_.gammas)
    if (!(g > 1)) f.fail("checks", "gammas", "expected Gamma > 1 (the layer must take off)");
  if (c_.wavePoint() == static_cast<int>(c_.gammas.size()))
    f.fail("checks", "wave_gamma", "expected one of [checks] gammas");
  if (std::set<double>(c_.gammas.begin(), c_.gammas.end()).size() != c_.gammas.size())
    f.fail("checks", "gammas", "expected distinct Gamma values");
  if (std::set<int>(c_.seeds.begin(), c_.seeds.end()).size() != c_.seeds.size())
    f.fail("particles", "seeds", "expected distinct seeds");
  if (!(c_.cycles >= 30)) f.fail("particles", "cycles", "expected at least 30 cycles");
}

ReadingsStudy::ReadingsStudy(StudyFile& f) {
  readKeys(f);
  const DrivePoint wave = c_.points()[c_.wavePoint()];
  for (Reading& r : c_.readings) {
    std::vector<std::string> o = r.overrides();
    o.push_back(fmt::format("drive.frequency={}", formatCompact(wave.frequency)));
    o.push_back(fmt::format("drive.gamma={}", formatCompact(wave.gamma)));
    const SceneDerived d = derive(c_.scenes.scene(f, 0, o));
    r.kappa_si = d.kappa_si;
    c_.wave_v0 = d.v0;
  }
  for (std::size_t r = 0; r < c_.readings.size(); ++r)
    for (int law = 0; law < kLaws; ++law)
      for (const DrivePoint& p : c_.points())
        for (int seed : c_.seeds) {
          std::vector<std::string> o = c_.readings[r].overrides();
          o.push_back(fmt::format("drive.frequency={}", formatCompact(p.frequency)));
          o.push_back(fmt::format("drive.gamma={}", formatCompact(p.gamma)));
          o.push_back(fmt::format("run.duration={:.6g}", c_.cycles / p.frequency));
          o.push_back(fmt::format("run.seed={}", seed));
          RunRequest q = runRequest(RunKind::Particles, c_.run(static_cast<int>(r), law, p, seed),
                                    c_.scenes.scene(f, law, o));
          q.window_cycles = c_.window;
          q.blocks = c_.blocks;
          requests_.push_back(std::move(q));
        }
}

void ReadingsStudy::analyse(const RunSet& runs, h5::File& results, Report& report) const {
  const ReadingsResults r = analyseReadings(c_, runs);
  writeReadingsResults(results, c_, r);
  reportReadings(c_, r, report);
}

std::unique_ptr<Study> makeReadingsStudy(StudyFile& file) {
  return std::make_unique<ReadingsStudy>(file);
}

}  // namespace granwave
