#include "studies/stability/SeedVote.hpp"

#include <stdexcept>

namespace granwave {

const char* criterionName(SolidCriterion c) {
  return c == SolidCriterion::bonds ? "bonds over 15 cycles" : "within one cycle";
}

const char* criterionKey(SolidCriterion c) {
  return c == SolidCriterion::bonds ? "" : "_within_cycle";
}

bool LayerVerdict::seedsAgree() const {
  // A question no seed answered is no disagreement; all seeds failing is agreement too.
  const auto same = [](const auto& v) { return v.of == 0 || v.unanimous(); };
  return same(state) && same(within_cycle_state) && same(period) && same(surface_wave) &&
         same(kinks) && (failed == 0 || failed == runs);
}

LayerVerdict voteOverSeeds(const std::vector<LayerPatterns>& patterns,
                           const std::vector<bool>& finished,
                           const std::vector<std::string>& messages) {
  if (patterns.size() != finished.size() || patterns.size() != messages.size())
    throw std::invalid_argument("voteOverSeeds: " + std::to_string(patterns.size()) +
                                " patterns, " + std::to_string(finished.size()) + " outcomes and " +
                                std::to_string(messages.size()) +
                                " messages; one of each per seed is needed");
  LayerVerdict v;
  v.runs = static_cast<int>(patterns.size());
  std::vector<std::string> states, within;
  std::vector<int> periods;
  std::vector<bool> waves, kinks;
  for (std::size_t k = 0; k < patterns.size(); ++k) {
    if (!finished[k]) {
      if (v.failed++ == 0) v.failure = messages[k];
      continue;
    }
    const LayerPatterns& p = patterns[k];
    periods.push_back(p.period);
    if (!p.available) continue;
    states.push_back(p.state);
    within.push_back(p.within_cycle_state);
    v.within_cycle_coordination += p.within_cycle_coordination;
    v.within_cycle_psi6 += p.within_cycle_psi6;
    v.lid_row += p.lid_row;
    waves.push_back(p.surface_wave);
    kinks.push_back(p.kinks > 0);
    v.psi6 += p.psi6;
    v.bonds_kept += p.bonds_kept;
    v.bonds_kept_per_cycle += p.bonds_kept_per_cycle;
    if (p.surface_wave) {
      v.surface_wave_amplitude_d += p.surface_wave_amplitude_d;
      if (v.surface_wave_mode == 0) v.surface_wave_mode = p.surface_wave_mode;
    }
  }
  v.state = mostFrequent(states);
  v.within_cycle_state = mostFrequent(within);
  v.period = mostFrequent(periods);
  v.surface_wave = mostFrequent(waves);
  v.kinks = mostFrequent(kinks);
  if (!states.empty()) {
    v.psi6 /= static_cast<double>(states.size());
    v.bonds_kept /= static_cast<double>(states.size());
    v.bonds_kept_per_cycle /= static_cast<double>(states.size());
    v.within_cycle_coordination /= static_cast<double>(states.size());
    v.within_cycle_psi6 /= static_cast<double>(states.size());
    v.lid_row /= static_cast<double>(states.size());
  }
  int n_waves = 0;
  for (bool w : waves) n_waves += w;
  if (n_waves > 0) v.surface_wave_amplitude_d /= n_waves;
  return v;
}

}  // namespace granwave
