#pragma once
// The numbers of the stability study: the seeds' verdict at every (law, f, Gamma) point, the
// hydro solver's period or failure on the same grid, the dry-wet differences per frequency,
// the paper's features checked, and the snapshots of the gallery; written under
// /results/stability (docs/studies.md).
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/run_files/RunOutputs.hpp"
#include "studies/stability/DifferenceBootstrap.hpp"
#include "studies/stability/SeedBootstrap.hpp"
#include "studies/stability/SpectrumWaves.hpp"
#include "studies/stability/StabilityFeatures.hpp"
#include "studies/stability/StabilityGrid.hpp"
#include "studies/stability/StabilityStudy.hpp"

namespace granwave {

// The classifier's states (docs/classification.md), in the order of their codes 0, 1, 2.
inline const std::vector<std::string> kLayerStates{"crystal", "amorphous", "liquid-like"};

// The hydro run at one point: not run, failed (with the reason), or its period (0: none).
struct HydroPoint {
  bool run = false, ok = false, periodic = false;
  int period = 0;
  std::string failure;
  std::string regime;  // fluidised, moves as a solid, or at rest (docs/hydro.md)
};

// The last recorded frame of one run whose state is `state` (positions in diameters).
struct GallerySnapshot {
  std::size_t state = 0;
  int law = 0, seed = 0;
  double frequency = 0, gamma = 0;
  LayerPatterns patterns;
  std::vector<double> x, z;     // / d, lab frame
  double plate = 0, width = 0;  // / d
};

struct StabilityResults {
  StabilityGrid grid;
  std::vector<HydroPoint> hydro[2];                            // [law][i_f * gammas + j_gamma]
  std::vector<HydroPoint> hydro_rough[2];                      // the same, rough particles
  std::vector<double> symbol_differences, period_differences;  // per frequency
  std::vector<double> symbol_differences_within_cycle;         // state by the second criterion
  std::vector<FeatureCheck> features;
  SeedBootstrap bootstrap;              // how the verdicts depend on the choice of seeds
  std::vector<double> seeds_per_point;  // seeds run at each point (more where they disagreed)
  int max_seeds = 0;
  std::vector<DifferenceCounts> difference_counts;  // the counts per f over seed resamples
  std::vector<GallerySnapshot> gallery;             // by state, then law, f, Gamma
  // The surface waves from the spectrum, beside the detector's: [law][i_f * gammas + j_gamma].
  std::vector<SpectrumWave> spectrum[2];
};

// The seeds run at a point: the study's, then any added where its seeds disagreed.
std::vector<int> seedsAt(const StabilityConfig& config, const RunSet& runs, double f, double gamma);
// Every point voted over its seeds; `seeds` receives every seed's classification.
StabilityGrid voteGrid(const StabilityConfig& config, const RunSet& runs, SeedPatterns& seeds);
StabilityResults analyseStability(const StabilityConfig& config, const RunSet& runs);
void writeStabilityResults(h5::File& file, const StabilityConfig& config,
                           const StabilityResults& results);

}  // namespace granwave
