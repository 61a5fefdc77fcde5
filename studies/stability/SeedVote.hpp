#pragma once
// One verdict per driving condition from several seeds (the stability study).
//
// The layer's state, pattern and period are properties of its attractor, but the attractor
// a run falls into can depend on the seed: the wet layer at f = 10 Hz, Gamma = 4 is period 2
// in 6 of 8 seeds and period 1 in 2 (docs/physics.md), and the states between the crystal
// and the liquid region keep 0.4-0.5 of their bonds (docs/classification.md), so one run
// decides them by chance. A stability diagram therefore labels each point with the most
// frequent answer over its seeds and says how many seeds gave it; a point whose seeds do not
// all agree is marked, so a reader sees which labels are coin flips.
#include <string>
#include <vector>

#include "coarse_grain/FieldsReader.hpp"

namespace granwave {

// The most frequent value and how many of the votes gave it. Ties go to the value seen first
// (seed order), so the verdict is deterministic.
template <class T>
struct Vote {
  T value{};
  int count = 0;  // votes for value
  int of = 0;     // votes cast
  bool unanimous() const { return of > 0 && count == of; }
};

template <class T>
Vote<T> mostFrequent(const std::vector<T>& votes) {
  Vote<T> v;
  v.of = static_cast<int>(votes.size());
  for (std::size_t i = 0; i < votes.size(); ++i) {
    int n = 0;
    for (const T& w : votes) n += w == votes[i];
    if (n > v.count) {
      v.count = n;
      v.value = votes[i];
    }
  }
  return v;
}

// The two solid criteria (docs/classification.md, "Two solid criteria"): neighbour bonds kept
// over the 15 observed cycles, and each cycle judged on its own from its most compact phase
// (coarse_grain/WithinCycleState.hpp), closer to the paper's inspection of one flight.
enum class SolidCriterion { bonds, within_cycle };
inline constexpr SolidCriterion kSolidCriteria[2] = {SolidCriterion::bonds,
                                                     SolidCriterion::within_cycle};
// "bonds over 15 cycles" / "within one cycle"
const char* criterionName(SolidCriterion c);
// Suffix of the criterion's keys in results.h5: "" / "_within_cycle"
const char* criterionKey(SolidCriterion c);

// The seeds' verdict on one (law, f, Gamma) point. Only classified runs vote (a failed run or
// one too short to classify does not); `runs` counts every seed, `failed` those whose run
// failed (their first reason in `failure`).
struct LayerVerdict {
  int runs = 0, failed = 0;
  std::string failure;
  Vote<std::string> state;               // "crystal", "amorphous", "liquid-like" (bonds)
  Vote<std::string> within_cycle_state;  // the same, by the within-cycle criterion
  Vote<int> period;                      // over the runs that finished, classified or not
  Vote<bool> surface_wave;               // detected or not
  Vote<bool> kinks;                      // at least one kink or none
  // Means over the voting runs: the two numbers the state comes from, and the wave's size.
  double psi6 = 0, bonds_kept = 0, bonds_kept_per_cycle = 0, surface_wave_amplitude_d = 0;
  int surface_wave_mode = 0;  // of the first voting run that has the wave
  // Means over the voting runs, within-cycle criterion: neighbours and <|psi6|> at the most
  // compact phase, and the particles pressed against the lid at the fullest phase of a cycle.
  double within_cycle_coordination = 0, within_cycle_psi6 = 0, lid_row = 0;
  const Vote<std::string>& stateBy(SolidCriterion c) const {
    return c == SolidCriterion::bonds ? state : within_cycle_state;
  }
  bool classified() const { return state.of > 0; }
  // Every vote cast (both states, period, waves, kinks) unanimous, and either no seed or every seed
  // failed.
  bool seedsAgree() const;
};

// `finished[k]` is false for a seed whose run failed (`messages[k]` says why); the patterns
// of such a seed are ignored. Throws std::invalid_argument if the three sizes differ.
LayerVerdict voteOverSeeds(const std::vector<LayerPatterns>& patterns,
                           const std::vector<bool>& finished,
                           const std::vector<std::string>& messages);

}  // namespace granwave
