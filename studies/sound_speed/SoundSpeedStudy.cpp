#include "studies/sound_speed/SoundSpeedStudy.hpp"

#include <fmt/format.h>

#include "studies/sound_speed/SoundSpeedAnalysis.hpp"
#include "studies/sound_speed/SoundSpeedReport.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

std::string SoundSpeedConfig::label(int law, int n, double gamma) {
  return particleLabel(law, fmt::format("N={} Gamma={}", n, formatCompact(gamma)));
}

SoundSpeedStudy::SoundSpeedStudy(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  c_.duration = f.number("particles", "duration", c_.duration);
  c_.seed = f.integer("particles", "seed", c_.seed);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.counts = f.integers("particles", "counts", c_.counts);
  c_.gammas = f.numbers("particles", "gammas", c_.gammas);
  c_.rows = f.integer("states", "rows", c_.rows);
  c_.gap = f.integer("states", "gap", c_.gap);
  if (c_.rows < 1) f.fail("states", "rows", "expected at least 1 row");
  if (c_.gap < 1) f.fail("states", "gap", "expected at least 1 row between front and state");
  if (c_.blocks < 2) f.fail("particles", "blocks", "expected at least 2 blocks for the errors");
  c_.scenes.loadBase(f);
  for (int law = 0; law < kLaws; ++law)
    for (int n : c_.counts)
      for (double gamma : c_.gammas) {
        RunRequest q = runRequest(
            RunKind::Particles, SoundSpeedConfig::label(law, n, gamma),
            c_.scenes.scene(f, law,
                            {fmt::format("particles.count={}", n),
                             fmt::format("drive.gamma={}", formatCompact(gamma)),
                             fmt::format("run.seed={}", c_.seed),
                             fmt::format("run.duration={}", formatCompact(c_.duration))}));
        q.window_cycles = c_.window;
        q.blocks = c_.blocks;
        requests_.push_back(std::move(q));
      }
}

void SoundSpeedStudy::analyse(const RunSet& runs, h5::File& results, Report& report) const {
  const SoundSpeedResults r = analyseSoundSpeed(c_, runs);
  writeSoundSpeedResults(results, r);
  reportSoundSpeed(c_, r, report);
}

std::unique_ptr<Study> makeSoundSpeedStudy(StudyFile& file) {
  return std::make_unique<SoundSpeedStudy>(file);
}

}  // namespace granwave
