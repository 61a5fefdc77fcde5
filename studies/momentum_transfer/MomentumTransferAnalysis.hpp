#pragma once
// The numbers of the momentum-transfer study: per seed the dry and wet run, the onsets of
// their strong impact fronts and r_x over the wet layer's impact wave; combined over seeds
// r~_x, the map r_x(z, t), the profiles of Fig. 7; written under /results/momentum_transfer.
#include <optional>
#include <string>
#include <vector>

#include "coarse_grain/FieldsReader.hpp"
#include "coarse_grain/MomentumDeficiency.hpp"
#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/momentum_transfer/BinaryImpactEstimate.hpp"
#include "studies/momentum_transfer/MomentumTransferStudy.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

// The paper's number (Huang, Sec. V, Fig. 8a) and the binary-collision argument (Sec. V).
inline const Measurement kPaperDeficiency{2.17, 0.56};
inline const Measurement kBinaryDeficiency{2.0, 0.0};
// docs/fields.md: the earlier measurement with this code (seed 1, 30 s, std over 35 phases).
inline const Measurement kEarlierDeficiency{0.60, 0.22};
inline constexpr double kPaperOnset = 0.88;  // the paper's impact begins at t/T = 0.88 (Sec. IV)

// A dry and a wet run of one seed, the onsets of their strong impact fronts, and r_x.
struct SeedPair {
  int seed = 0;
  int other_window = 0;  // 0: the study's window; else the runs with this other window
  std::string failure;   // empty: both runs usable
  std::optional<FieldsRecord> layer[2];
  double onset[2] = {NAN, NAN};  // t/T within the window
  bool found[2] = {false, false};
  int on[2] = {0, 0};  // phase index of the onset
  int blocks = 0, per_cycle = 0;

  Deficiency pooled;                     // same plate phase, rows cut
  std::vector<Deficiency> blocks_r;      // the same per block
  Measurement r, r_all_rows, r_aligned;  // over the wave window; error from the blocks
  Measurement rms[2];                    // m/s, over the (z, t) cells entering r~_x
  double block_ratio[2] = {NAN, NAN};    // <RMS of one block> / <pooled RMS>
  // Mean square RMS(v_x) split into the phase-locked flow and the statistical noise of the
  // cell means: a block pools 1/B of the cycles, so its noise variance is B times the
  // pooled one: <b^2> = S^2 + B N^2, P^2 = S^2 + N^2 (if the flow is the same in every block).
  double signal2[2] = {NAN, NAN}, noise_share[2] = {NAN, NAN};
  double r_signal = NAN;                     // sqrt(S^2_dry / S^2_wet) over the window
  double above_one = NAN;                    // fraction of the cells of r~_x with r_x > 1
  std::vector<double> row_mean_around_wave;  // r~_x(t) at the study's tau
  std::vector<bool> wave;                    // the phases of the wave window
};

// Mean over seeds of a profile at one phase per seed and layer, with a one-sigma band.
struct LayerProfile {
  std::vector<double> mean, low, high;
};

// Fig. 7: v~_z and RMS(v_x) over v0 at the paper's phase, literally (the same plate phase)
// and at the same stage of each layer's own impact.
struct ImpactProfiles {
  std::vector<double> z;              // m, lab frame
  std::vector<double> literal_phase;  // per usable seed: the wet window phase shown
  LayerProfile vz_literal[2], rms_literal[2], vz_onset[2], rms_onset[2];
};

struct MomentumTransferResults {
  std::vector<SeedPair> pairs;
  int n_wave = 1, n_margin = 0, per_cycle = 100, nz = 0, j0 = -1, j1 = -1;
  Measurement r, r_all_rows, r_aligned, rms[2], above_one, r_signal, noise_share[2];
  int window = 2, other_window = 1;
  Measurement r_other_window;         // r~_x from the runs with the other phase window
  std::vector<SeedPair> other_pairs;  // their seeds
  double window_std = NAN, z_paper = NAN, z_binary = NAN;
  std::vector<double> tau, row_mean, row_error;  // around the wave, from the wet onset
  std::vector<double> map;                       // [z][tau], mean over seeds
  ImpactProfiles profiles;                       // when some seed has both runs
  BinaryImpactEstimate binary_impact;            // <(1+e_dry)/(1+e_wet)> over the wave's impacts
  std::vector<const SeedPair*> ok() const;       // the seeds with both runs usable
};

MomentumTransferResults analyseMomentumTransfer(const MomentumTransferConfig& config,
                                                const RunSet& runs);
void writeMomentumTransferResults(h5::File& file, const MomentumTransferConfig& config,
                                  const MomentumTransferResults& results);

}  // namespace granwave
