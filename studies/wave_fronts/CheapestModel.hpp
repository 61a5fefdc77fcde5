#pragma once
// The cheapest model that reproduces the particles, scene by scene (docs/studies.md, "Cost per
// answer at equal accuracy"): every model the study ran on a scene, with what one answer cost
// it (CPU seconds) and how far its answer lies from the full particle model's (the accuracy
// axis), and the cheapest one shown to reproduce the particles within the study's tolerances.
// "Model no more than a scene needs", answered per scene from measured runs.
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/method_comparison/MethodComparison.hpp"
#include "studies/statistics/Measurement.hpp"
#include "studies/wave_analysis/VelocityFronts.hpp"

namespace granwave {

struct WaveFrontsConfig;
struct WaveFrontsResults;

// One model's answer on one scene.
struct ModelCost {
  std::string model;
  bool continuum = false, reference = false, failed = false;
  double cpu = NAN;   // CPU-s per answer
  Measurement speed;  // velocity-jump front speed (m/s), the straight-line fit
  // N sweep: the front's transits through the layer's mass (0.1-0.5, 0.5-0.9), the particles'
  // as the continuum's are compared with them (particleTransit); empty on the paper's scenes.
  bool has_transits = false;
  TransitSpeeds transit[2];
  // (answer - the particles') / the particles', with its one-sigma error (both errors): the
  // accuracy axis. The answer is the fit, or on the N sweep the transit farthest from the
  // particles' among those both resolve (`gap_on` says which).
  Measurement gap;
  std::string gap_on = "fit";
  std::string periods;      // the layer's period(s) in drive cycles ("" when failed)
  Match match = Match::no;  // the reference: yes
  std::string why;          // how the match was judged, or why the model has no answer
};

struct SceneCost {
  std::string scene;              // "paper's scene, dry", "N = 300, wet", ...
  std::vector<ModelCost> models;  // the full particle model first
  int cheapest = 0;               // the cheapest model shown to reproduce (0: the particles)
  std::vector<int> cheaper_open;  // cheaper than it, neither shown to reproduce nor not to
};

// Sets `cheapest` (the reference always reproduces itself; a model without a cost is never
// the cheapest) and `cheaper_open` (cheaper models still `not_yet` or `cannot_tell`).
void pickCheapest(SceneCost& scene);

// A deterministic (continuum) answer against the particles' at a sweep point: its front speed
// by frontMatch, or, where the particles' front crosses the layer faster than the phases
// resolve, against the lower bound they give; and the period, when every seed agrees on one.
Match sweepMatch(const Measurement& continuum, int continuum_period, const Measurement& particles,
                 double particles_bound, const std::vector<int>& particle_periods, double tolerance,
                 std::string& why);

// The N sweep's judgement by the transits (docs/studies.md, item 11): the period as in
// sweepMatch, then each transit of the continuum against the particles' (`transit`): the worst
// verdict of those compared (no, then not yet, then cannot tell, then yes); by the fit
// (sweepMatch) only where no transit can be compared (the particles' fronts reach neither).
Match sweepTransitMatch(const VelocityFronts& continuum, int continuum_period,
                        const VelocityFronts& particles, const std::vector<int>& particle_periods,
                        double tolerance, std::string& why);

// The paper's dry and wet scenes (from the model hierarchy), then each count of the N sweep
// for each law (particles against the continuum with the velocity-dependent closure).
std::vector<SceneCost> cheapestModels(const WaveFrontsConfig& config,
                                      const WaveFrontsResults& results);
// Under root/cost/cheapest (with the other CPU times: a measurement of this machine).
void writeCheapestModels(h5::File& file, const std::string& root,
                         const std::vector<SceneCost>& scenes);

}  // namespace granwave
