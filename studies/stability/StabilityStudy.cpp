#include "studies/stability/StabilityStudy.hpp"

#include <fmt/format.h>

#include <set>

#include "studies/framework/Measurement.hpp"
#include "studies/stability/StabilityAnalysis.hpp"
#include "studies/stability/StabilityReport.hpp"

namespace granwave {

std::string StabilityConfig::particleRun(int law, double f, double gamma, int seed) {
  return particleLabel(
      law, fmt::format("f={} Gamma={} seed {}", formatCompact(f), formatCompact(gamma), seed));
}

std::string StabilityConfig::hydroRun(int law, double f, double gamma, bool rough) {
  return hydroLabel(law, fmt::format("{}f={} Gamma={}", rough ? "rough " : "", formatCompact(f),
                                     formatCompact(gamma)));
}

void StabilityStudy::readKeys(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  c_.frequencies = f.numbers("grid", "frequencies", c_.frequencies);
  c_.gammas = f.numbers("grid", "gammas", c_.gammas);
  c_.cycles = f.number("particles", "cycles", c_.cycles);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.hydro = f.boolean("hydro", "enabled", c_.hydro);
  c_.hydro_rough = f.boolean("hydro", "rough", c_.hydro_rough) && c_.hydro;
  c_.gallery_per_state = f.integer("gallery", "per_state", c_.gallery_per_state);
  for (double v : c_.frequencies)
    if (!(v > 0)) f.fail("grid", "frequencies", "expected positive frequencies in Hz");
  for (double v : c_.gammas)
    if (!(v > 1)) f.fail("grid", "gammas", "expected Gamma > 1 (the layer must take off)");
  if (std::set<double>(c_.frequencies.begin(), c_.frequencies.end()).size() !=
      c_.frequencies.size())
    f.fail("grid", "frequencies", "expected distinct frequencies");
  if (std::set<double>(c_.gammas.begin(), c_.gammas.end()).size() != c_.gammas.size())
    f.fail("grid", "gammas", "expected distinct Gamma values");
  if (std::set<int>(c_.seeds.begin(), c_.seeds.end()).size() != c_.seeds.size())
    f.fail("particles", "seeds", "expected distinct seeds");
  if (!(c_.cycles >= 30)) f.fail("particles", "cycles", "expected at least 30 cycles");
}

StabilityStudy::StabilityStudy(StudyFile& f) {
  readKeys(f);
  for (int law = 0; law < kLaws; ++law)
    for (double fr : c_.frequencies)
      for (double gamma : c_.gammas) {
        std::vector<std::string> o{fmt::format("drive.frequency={}", formatCompact(fr)),
                                   fmt::format("drive.gamma={}", formatCompact(gamma)),
                                   fmt::format("run.duration={:.6g}", c_.cycles / fr)};
        for (int seed : c_.seeds) {
          std::vector<std::string> os = o;
          os.push_back(fmt::format("run.seed={}", seed));
          RunRequest q =
              runRequest(RunKind::Particles, StabilityConfig::particleRun(law, fr, gamma, seed),
                         c_.scenes.scene(f, law, os));
          q.window_cycles = c_.window;
          q.blocks = c_.blocks;
          requests_.push_back(std::move(q));
        }
        // The continuum has no seed; the scene names the first one only so that it is
        // complete (the seed does not enter the hydro solver).
        o.push_back(fmt::format("run.seed={}", c_.seeds.front()));
        if (c_.hydro) addHydro(f, law, fr, gamma, o, false);
        if (c_.hydro_rough) addHydro(f, law, fr, gamma, o, true);
      }
}

void StabilityStudy::addHydro(StudyFile& f, int law, double fr, double gamma,
                              std::vector<std::string> o, bool rough) {
  if (rough) o.push_back("hydro.particles=\"rough\"");
  RunRequest q = runRequest(RunKind::Hydro, StabilityConfig::hydroRun(law, fr, gamma, rough),
                            c_.scenes.scene(f, law, o));
  q.failure_note = "failure is a result (the continuum's stability map)";
  requests_.push_back(std::move(q));
}

void StabilityStudy::analyse(const RunSet& runs, h5::File& results, Report& report) const {
  const StabilityResults r = analyseStability(c_, runs);
  writeStabilityResults(results, c_, r);
  reportStability(c_, r, report);
}

std::unique_ptr<Study> makeStabilityStudy(StudyFile& file) {
  return std::make_unique<StabilityStudy>(file);
}

}  // namespace granwave
