#pragma once
// What `fields` (offline) and `simulate --fields` (live) share: the configurations of the
// averager and the surface recorder and the analysis context from a scene, and the printed
// summary of the fields.
#include <string>

#include "coarse_grain/FieldsAnalysis.hpp"
#include "coarse_grain/SurfaceRecorder.hpp"
#include "scene/Scene.hpp"

namespace granwave {

PhaseAveragerConfig phaseAveragerConfig(const Scene& scene, int cycles_per_window, int blocks,
                                        int fixed_discard);
// The surface recorder of a run's fields: every recorded phase, the scene's box.
SurfaceRecorderConfig surfaceRecorderConfig(const Scene& scene);
// Its analysis from the first steady cycle the averager pooled.
SurfaceWaveAnalysis surfaceWaves(const SurfaceRecorder& recorder, const PhaseAverager& averager);
FieldsContext fieldsContext(const Scene& scene, const std::string& source,
                            const std::string& scene_toml, int layer_period);
std::string formatFieldsSummary(const FieldsAnalysis& analysis);

}  // namespace granwave
