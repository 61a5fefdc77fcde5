#pragma once
// The paper's binary-impact argument for the momentum-transfer ratio (Huang, Sec. V), at the
// speeds of the layer's own impacts. In an impact at normal speed v the momentum passed along
// the line of centres is (m/2)(1 + e(v)) v, so a dry and a wet impact at the same speed pass
// on momenta in the ratio (1 + e_dry(v)) / (1 + e_wet(v)); with e_dry = 1 and e_wet = 0 (below
// the wet onset speed) it is the paper's 2. Here the ratio is averaged over the pair impacts
// of the wave window, weighted by their number:
//     R = sum_k c_k (1 + e_dry(v_k)) / (1 + e_wet(v_k)) / sum_k c_k,
// c_k the impacts with normal speed in bin k (centre v_k) of the run's pair-impact histogram
// (RUN.h5 /granwave/pair_impacts) in the phases of the wave window, e_dry and e_wet the laws of
// the study's two scenes. Where e_dry >= e_wet at every speed, 1 <= R <= 2. Its uncertainty:
// a bootstrap over seeds that pools the drawn seeds' histograms (SeedResampling.hpp).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "particles/Restitution.hpp"
#include "studies/contract/Study.hpp"
#include "studies/momentum_transfer/MomentumTransferStudy.hpp"
#include "studies/statistics/SeedResampling.hpp"

namespace granwave {

// Impacts per normal-speed bin of width speed_max / counts.size() (the last bin holds the
// faster ones too).
struct ImpactSpeedCounts {
  double speed_max = 0;
  std::vector<std::uint64_t> counts;
};

// R over the impacts of `h`; NaN without impacts.
double lawRatioOverImpacts(const ImpactSpeedCounts& h, const Restitution& dry,
                           const Restitution& wet);

// One seed's impacts in its wave window (the phases r~_x averages), of the dry and wet run.
struct SeedImpacts {
  int seed = 0;
  ImpactSpeedCounts law[2];
};

// R from the dry run's and from the wet run's impacts ([0], [1]).
struct BinaryImpactEstimate {
  std::string missing;  // empty: estimated; else why not
  std::vector<SeedImpacts> seeds;
  std::vector<double> per_seed[2];
  double pooled[2] = {NAN, NAN};  // all seeds' impacts together
  PercentileInterval bootstrap[2];
  std::uint64_t impacts[2] = {0, 0};
  double below_onset[2] = {NAN, NAN};  // share of the impacts below the wet onset speed
  double onset_speed = 0;              // m/s, the wet law's
};

inline constexpr int kImpactResamples = 1000;
// `wave[i]`: the phases of seed `seeds[i]`'s wave window (the fields' phases, which the
// histogram's phase bins equal); runs whose file has no histogram leave the estimate missing.
BinaryImpactEstimate binaryImpactEstimate(const MomentumTransferConfig& c, const RunSet& runs,
                                          const std::vector<int>& seeds,
                                          const std::vector<std::vector<bool>>& wave,
                                          int resamples = kImpactResamples);
// Under `group`/binary_impact: pooled and bootstrap values per law's impacts, per seed.
void writeBinaryImpactEstimate(h5::File& file, const std::string& group,
                               const BinaryImpactEstimate& e);

}  // namespace granwave
