#include "studies/cli/StudyKinds.hpp"

#include "studies/effective_restitution/EffectiveRestitutionStudy.hpp"
#include "studies/momentum_transfer/MomentumTransferStudy.hpp"
#include "studies/readings/ReadingsStudy.hpp"
#include "studies/sound_speed/SoundSpeedStudy.hpp"
#include "studies/stability/StabilityStudy.hpp"
#include "studies/surface_waves/SurfaceWavesStudy.hpp"
#include "studies/wave_fronts/WaveFrontsStudy.hpp"

namespace granwave {

std::unique_ptr<Study> makeStudy(StudyFile& file) {
  const std::string& kind = file.kind();
  if (kind == "wave-fronts") return makeWaveFrontsStudy(file);
  if (kind == "effective-restitution") return makeEffectiveRestitutionStudy(file);
  if (kind == "sound-speed") return makeSoundSpeedStudy(file);
  if (kind == "stability") return makeStabilityStudy(file);
  if (kind == "momentum-transfer") return makeMomentumTransferStudy(file);
  if (kind == "readings") return makeReadingsStudy(file);
  if (kind == "surface-waves") return makeSurfaceWavesStudy(file);
  file.fail("study", "kind",
            "unknown study kind; valid kinds: wave-fronts, sound-speed, effective-restitution, "
            "momentum-transfer, stability, readings, surface-waves");
}

}  // namespace granwave
