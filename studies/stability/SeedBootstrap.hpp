#pragma once
// How stable the stability study's verdicts are against the choice of seeds: a bootstrap over
// seeds (Efron & Tibshirani, "An Introduction to the Bootstrap", 1993, ch. 6).
//
// The verdict at a point is the most frequent over its seeds (SeedVote.hpp), and the paper's
// features and the dry-wet difference counts are read from those verdicts. Each resample
// draws, independently at every (f, Gamma) point (the runs of different points are independent
// simulations), as many seeds as were run there, with replacement, and the same draw for the
// dry and the wet layer of the point; the seeds vote again and the features are checked again.
// Reported: for each feature, the share of resamples whose verdict equals the full grid's (1:
// no seed choice changes it; near 1/2: a coin flip). A point whose seeds all agree is the same
// in every resample. (The dry-wet difference counts have their own bootstrap,
// DifferenceBootstrap.hpp.) The draws are fixed 64-bit Mersenne Twister sequences, one per
// point (SeedResampling.hpp), so the bootstrap is the same on every build.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "coarse_grain/FieldsReader.hpp"
#include "studies/stability/StabilityGrid.hpp"

namespace granwave {

// Every seed's classification at every point: [law][point][seed], with whether its run
// finished and the run's message (voteOverSeeds' inputs).
struct SeedPatterns {
  std::vector<std::vector<LayerPatterns>> patterns[2];
  std::vector<std::vector<bool>> finished[2];
  std::vector<std::vector<std::string>> messages[2];
};

// The verdict of one law at point p voted again by the seeds `draw` (indices into the point's
// seeds, repeats allowed): the step every bootstrap over seeds repeats.
LayerVerdict revotePoint(const SeedPatterns& s, int law, std::size_t p,
                         const std::vector<std::size_t>& draw);

// Draws of seeds for every resample: [point][resample] -> indices into the point's seeds.
using PointDraws = std::vector<std::vector<std::vector<std::size_t>>>;
// `resamples` independent draws at every point, each of as many seeds as the point ran;
// point p's come from the sequence seeded rng_seed + p.
PointDraws pointDraws(const SeedPatterns& s, int resamples, std::uint64_t rng_seed);
// Every point's seeds once each: the full grid as one "resample".
PointDraws allSeeds(const SeedPatterns& s);
// The grid voted again from resample r of `draws`; `frame` gives frequencies and Gamma values.
StabilityGrid revoteGrid(const StabilityGrid& frame, const SeedPatterns& s, const PointDraws& draws,
                         std::size_t r);

// The share of resamples from which a stability feature counts as decided (docs/studies.md,
// "Stability over seeds").
inline constexpr double kDecidedAgreement = 0.9;

struct SeedBootstrap {
  int resamples = 0;
  // Feature key -> share of resamples with the full grid's verdict.
  std::map<std::string, double> verdict_agreement;
};

// `grid`: the full grid's frequencies and Gamma values (its verdicts are not used).
SeedBootstrap bootstrapOverSeeds(const StabilityGrid& grid, const SeedPatterns& seeds,
                                 int resamples = 200);

}  // namespace granwave
