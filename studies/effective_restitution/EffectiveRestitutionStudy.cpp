#include "studies/effective_restitution/EffectiveRestitutionStudy.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "scene/SceneDerived.hpp"
#include "studies/effective_restitution/EffectiveRestitutionAnalysis.hpp"
#include "studies/effective_restitution/EffectiveRestitutionReport.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

std::string EffectiveRestitutionConfig::coolingLabel(int law, double nu, bool rough) {
  return particleLabel(
      law, fmt::format("cooling nu={}{}", formatCompact(nu), rough ? " with friction" : ""));
}

std::string EffectiveRestitutionConfig::drivenLabel(int law, int seed) {
  return particleLabel(law, fmt::format("seed {}", seed));
}

std::string EffectiveRestitutionConfig::hydroLabel(double e) {
  return fmt::format("hydro constant e={}", formatCompact(e));
}

void EffectiveRestitutionStudy::readKeys(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  c_.duration = f.number("driven", "duration", c_.duration);
  c_.seeds = f.integers("driven", "seeds", c_.seeds);
  c_.window = f.integer("driven", "window_cycles", c_.window);
  c_.blocks = f.integer("driven", "blocks", c_.blocks);
  c_.cooling_nu = f.numbers("cooling", "area_fractions", c_.cooling_nu);
  c_.cooling_count = f.integer("cooling", "count", c_.cooling_count);
  c_.cooling_t_start = f.number("cooling", "initial_temperature", c_.cooling_t_start);
  c_.cooling_t_end = f.number("cooling", "lowest_temperature", c_.cooling_t_end);
  c_.cooling_duration = f.number("cooling", "duration", c_.cooling_duration);
  c_.cooling_record = f.number("cooling", "record_interval", c_.cooling_record);
  c_.cooling_bins = f.integer("cooling", "temperature_bins", c_.cooling_bins);
  c_.hydro_e = f.numbers("hydro_fit", "e", c_.hydro_e);
  for (double nu : c_.cooling_nu)
    if (!(nu > 0 && nu < 0.8)) f.fail("cooling", "area_fractions", "expected values in (0, 0.8)");
  if (!(c_.cooling_t_end > 0 && c_.cooling_t_end < c_.cooling_t_start))
    f.fail("cooling", "lowest_temperature", "expected 0 < lowest < initial_temperature");
  if (c_.hydro_e.size() < 3) f.fail("hydro_fit", "e", "expected at least 3 values to fit");
  for (double e : c_.hydro_e)
    if (!(e > 0 && e <= 1)) f.fail("hydro_fit", "e", "expected values in (0, 1]");
}

// Free cooling in a fully periodic square box at the layer's densities, no gravity.
void EffectiveRestitutionStudy::addCoolingRuns(const StudyFile& f, int law) {
  const double d = c_.scenes.base[law].particles.diameter;
  const double T0 = derive(c_.scenes.base[law]).T0;
  for (double nu : c_.cooling_nu)
    for (int rough = 0; rough < 2; ++rough) {
      const double side = std::sqrt(c_.cooling_count * std::numbers::pi * d * d / (4 * nu));
      std::vector<std::string> o{
          "container.periodic_x=true",
          "container.periodic_z=true",
          "drive.frequency=0",
          "run.gravity=0",
          fmt::format("particles.count={}", c_.cooling_count),
          fmt::format("container.width={:.9g}", side),
          fmt::format("container.height={:.9g}", side),
          fmt::format("initial.temperature={:.9g}", c_.cooling_t_start * T0),
          "initial.placement=\"lattice\"",
          fmt::format("run.record_interval={}", formatCompact(c_.cooling_record)),
          fmt::format("run.duration={}", formatCompact(c_.cooling_duration)),
          fmt::format("run.seed={}", c_.seeds.front())};
      if (!rough) o.emplace_back("contact.friction=0");
      RunRequest q =
          runRequest(RunKind::Particles, EffectiveRestitutionConfig::coolingLabel(law, nu, rough),
                     c_.scenes.scene(f, law, o));
      q.fields = false;
      requests_.push_back(std::move(q));
    }
}

EffectiveRestitutionStudy::EffectiveRestitutionStudy(StudyFile& f) {
  readKeys(f);
  c_.scenes.loadBase(f);
  for (int law = 0; law < kLaws; ++law) {
    for (int seed : c_.seeds) {
      RunRequest q =
          runRequest(RunKind::Particles, EffectiveRestitutionConfig::drivenLabel(law, seed),
                     c_.scenes.scene(f, law,
                                     {fmt::format("run.seed={}", seed),
                                      fmt::format("run.duration={}", formatCompact(c_.duration))}));
      q.window_cycles = c_.window;
      q.blocks = c_.blocks;
      requests_.push_back(std::move(q));
    }
    addCoolingRuns(f, law);
  }
  // Constant-e hydro: the law's parameters do not enter, so the dry scene serves both.
  for (double e : c_.hydro_e)
    requests_.push_back(
        runRequest(RunKind::Hydro, EffectiveRestitutionConfig::hydroLabel(e),
                   c_.scenes.scene(f, 0,
                                   {"hydro.restitution_model=\"constant\"",
                                    fmt::format("contact.e={}", formatCompact(e))})));
}

void EffectiveRestitutionStudy::analyse(const RunSet& runs, h5::File& results,
                                        Report& report) const {
  const EffectiveRestitutionResults r = analyseEffectiveRestitution(c_, runs);
  writeEffectiveRestitutionResults(results, r);
  reportEffectiveRestitution(c_, r, report);
}

std::unique_ptr<Study> makeEffectiveRestitutionStudy(StudyFile& file) {
  return std::make_unique<EffectiveRestitutionStudy>(file);
}

}  // namespace granwave
