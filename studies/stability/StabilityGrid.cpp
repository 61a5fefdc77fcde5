#include "studies/stability/StabilityGrid.hpp"

namespace granwave {

const char* differenceKey(Difference d) {
  constexpr const char* keys[] = {"state", "state_within_cycle", "waves", "kinks",
                                  "any",   "any_within_cycle"};
  return keys[static_cast<int>(d)];
}

const char* differenceName(Difference d) {
  constexpr const char* names[] = {"state (bonds)", "state (within one cycle)",
                                   "surface waves", "kinks",
                                   "any (bonds)",   "any (within one cycle)"};
  return names[static_cast<int>(d)];
}

bool StabilityGrid::differ(std::size_t i, std::size_t j, Difference d) const {
  const LayerVerdict &a = at(0, i, j), &b = at(1, i, j);
  if (!a.classified() || !b.classified()) return false;
  const bool waves = a.surface_wave.value != b.surface_wave.value;
  const bool kinks = a.kinks.value != b.kinks.value;
  const bool state = a.state.value != b.state.value;
  const bool within = a.within_cycle_state.value != b.within_cycle_state.value;
  switch (d) {
    case Difference::state:
      return state;
    case Difference::state_within_cycle:
      return within;
    case Difference::surface_waves:
      return waves;
    case Difference::kinks:
      return kinks;
    case Difference::any:
      return state || waves || kinks;
    case Difference::any_within_cycle:
      return within || waves || kinks;
  }
  return false;
}

std::vector<double> StabilityGrid::differencesPerFrequency(Difference d) const {
  std::vector<double> n(frequencies.size(), 0);
  for (std::size_t i = 0; i < frequencies.size(); ++i)
    for (std::size_t j = 0; j < gammas.size(); ++j) n[i] += differ(i, j, d);
  return n;
}

bool StabilityGrid::symbolsDiffer(std::size_t i, std::size_t j, SolidCriterion c) const {
  return differ(i, j, c == SolidCriterion::bonds ? Difference::any : Difference::any_within_cycle);
}

bool StabilityGrid::periodsDiffer(std::size_t i, std::size_t j) const {
  const LayerVerdict &a = at(0, i, j), &b = at(1, i, j);
  if (a.period.of == 0 || b.period.of == 0) return false;
  return a.period.value != b.period.value;
}

std::vector<double> StabilityGrid::symbolDifferencesPerFrequency(SolidCriterion c) const {
  std::vector<double> n(frequencies.size(), 0);
  for (std::size_t i = 0; i < frequencies.size(); ++i)
    for (std::size_t j = 0; j < gammas.size(); ++j) n[i] += symbolsDiffer(i, j, c);
  return n;
}

std::vector<double> StabilityGrid::periodDifferencesPerFrequency() const {
  std::vector<double> n(frequencies.size(), 0);
  for (std::size_t i = 0; i < frequencies.size(); ++i)
    for (std::size_t j = 0; j < gammas.size(); ++j) n[i] += periodsDiffer(i, j);
  return n;
}

}  // namespace granwave
