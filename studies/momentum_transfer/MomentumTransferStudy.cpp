#include "studies/momentum_transfer/MomentumTransferStudy.hpp"

#include <fmt/format.h>

#include "studies/momentum_transfer/MomentumTransferAnalysis.hpp"
#include "studies/momentum_transfer/MomentumTransferReport.hpp"

namespace granwave {

std::string MomentumTransferConfig::label(int law, int seed) {
  return particleLabel(law, fmt::format("seed {}", seed));
}

std::string MomentumTransferConfig::otherWindowLabel(int law, int seed, int window) {
  return particleLabel(law, fmt::format("seed {}, {}-cycle window", seed, window));
}

MomentumTransferStudy::MomentumTransferStudy(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  c_.duration = f.number("particles", "duration", c_.duration);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.profile_phase = f.number("analysis", "profile_phase", c_.profile_phase);
  c_.wave_duration = f.number("analysis", "wave_duration", c_.wave_duration);
  c_.margin = f.number("analysis", "margin", c_.margin);
  c_.min_rms = f.number("analysis", "min_rms", c_.min_rms);
  c_.min_area_fraction = f.number("analysis", "min_area_fraction", c_.min_area_fraction);
  if (!(c_.duration > 0)) f.fail("particles", "duration", "expected a positive time in s");
  if (c_.seeds.empty()) f.fail("particles", "seeds", "expected at least one seed");
  if (c_.window < 1 || c_.window > 4) f.fail("particles", "window_cycles", "expected 1 to 4");
  if (c_.blocks < 2) f.fail("particles", "blocks", "expected at least 2");
  if (!(c_.profile_phase >= 0 && c_.profile_phase < 1))
    f.fail("analysis", "profile_phase", "expected t/T in [0, 1)");
  if (!(c_.wave_duration > 0 && c_.wave_duration <= 1))
    f.fail("analysis", "wave_duration", "expected a fraction of the period in (0, 1]");
  if (!(c_.margin >= 0 && c_.margin <= 0.5))
    f.fail("analysis", "margin", "expected a fraction of the period in [0, 0.5]");
  if (!(c_.min_rms >= 0)) f.fail("analysis", "min_rms", "expected a velocity >= 0 in m/s");
  if (!(c_.min_area_fraction >= 0 && c_.min_area_fraction < 0.9))
    f.fail("analysis", "min_area_fraction", "expected a value in [0, 0.9)");

  c_.scenes.loadBase(f);
  for (int law = 0; law < kLaws; ++law)
    if (!(c_.scenes.base[law].drive.frequency > 0))
      f.fail("scenes", kLawNames[law], "the momentum-transfer study needs a driven scene");
  for (int law = 0; law < kLaws; ++law)
    for (int seed : c_.seeds) {
      RunRequest q = runRequest(RunKind::Particles, MomentumTransferConfig::label(law, seed),
                                c_.scenes.scene(f, law,
                                                {fmt::format("run.seed={}", seed),
                                                 fmt::format("run.duration={:g}", c_.duration)}));
      q.window_cycles = c_.window;
      q.blocks = c_.blocks;
      RunRequest other = q;  // the same trajectory (scene and seed), the other window
      other.label = MomentumTransferConfig::otherWindowLabel(law, seed, c_.otherWindow());
      other.window_cycles = c_.otherWindow();
      requests_.push_back(std::move(q));
      requests_.push_back(std::move(other));
    }
}

void MomentumTransferStudy::analyse(const RunSet& runs, h5::File& results, Report& report) const {
  const MomentumTransferResults r = analyseMomentumTransfer(c_, runs);
  writeMomentumTransferResults(results, c_, r);
  reportMomentumTransfer(c_, r, report);
}

std::unique_ptr<Study> makeMomentumTransferStudy(StudyFile& file) {
  return std::make_unique<MomentumTransferStudy>(file);
}

}  // namespace granwave
