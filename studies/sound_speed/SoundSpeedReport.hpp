#pragma once
// The sound-speed study's report: how often each theory holds, measured against predicted
// front speeds, every front's comparison and states. Figures, tables and prose only.
#include "studies/report/Report.hpp"
#include "studies/sound_speed/SoundSpeedAnalysis.hpp"

namespace granwave {

void reportSoundSpeed(const SoundSpeedConfig& config, const SoundSpeedResults& results,
                      Report& report);

}  // namespace granwave
