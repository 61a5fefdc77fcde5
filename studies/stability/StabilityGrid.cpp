#include "studies/stability/StabilityGrid.hpp"

namespace granwave {

bool StabilityGrid::symbolsDiffer(std::size_t i, std::size_t j, SolidCriterion c) const {
  const LayerVerdict &a = at(0, i, j), &b = at(1, i, j);
  if (!a.classified() || !b.classified()) return false;
  return a.stateBy(c).value != b.stateBy(c).value || a.surface_wave.value != b.surface_wave.value ||
         a.kinks.value != b.kinks.value;
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
