#include "coarse_grain/StateClassifier.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

struct Displacements {
  std::vector<double> dx, dz;
  double mean_dx = 0, mean_dz = 0;
};

Displacements displacements(const Snapshot& before, const Snapshot& after, double width,
                            bool periodic_x) {
  if (before.x.size() != after.x.size() || before.z.size() != after.z.size() ||
      before.x.size() != before.z.size())
    throw std::invalid_argument("relative displacement: snapshots hold " +
                                std::to_string(before.x.size()) + " and " +
                                std::to_string(after.x.size()) +
                                " particles (positions x, z); the same particles are needed");
  if (periodic_x && !(width > 0))
    throw std::invalid_argument("relative displacement: periodic x needs a positive width");
  const std::size_t n = before.x.size();
  Displacements d;
  d.dx.resize(n);
  d.dz.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    double rx = after.x[j] - before.x[j];
    // Minimum image: valid while a particle moves less than L_x / 2 per cycle.
    if (periodic_x) rx -= width * std::round(rx / width);
    d.dx[j] = rx;
    d.dz[j] = after.z[j] - before.z[j];
    d.mean_dx += rx / static_cast<double>(n);
    d.mean_dz += d.dz[j] / static_cast<double>(n);
  }
  return d;
}

double relativeDisplacement(const Snapshot& before, const Displacements& d, double width,
                            bool periodic_x, double cutoff) {
  const std::vector<std::vector<int>> nb =
      neighboursWithin(before.x, before.z, cutoff, width, periodic_x);
  const std::size_t n = d.dx.size();
  if (n == 0) return 0;
  double sum = 0;
  for (std::size_t j = 0; j < n; ++j) {
    double ref_x = d.mean_dx, ref_z = d.mean_dz;  // isolated: against the whole layer
    if (!nb[j].empty()) {
      ref_x = ref_z = 0;
      for (int k : nb[j]) ref_x += d.dx[k], ref_z += d.dz[k];
      ref_x /= static_cast<double>(nb[j].size());
      ref_z /= static_cast<double>(nb[j].size());
    }
    sum += std::hypot(d.dx[j] - ref_x, d.dz[j] - ref_z);
  }
  return sum / static_cast<double>(n);
}

}  // namespace

std::string_view toString(LayerState state) {
  switch (state) {
    case LayerState::crystal:
      return "crystal";
    case LayerState::amorphous:
      return "amorphous";
    case LayerState::liquid_like:
      return "liquid-like";
  }
  return "unknown";
}

double bondsKept(const Snapshot& before, const Snapshot& after, double width, bool periodic_x,
                 double bond_cutoff, double broken_beyond) {
  if (before.x.size() != after.x.size() || before.z.size() != after.z.size() ||
      before.x.size() != before.z.size())
    throw std::invalid_argument("bond survival: snapshots hold " + std::to_string(before.x.size()) +
                                " and " + std::to_string(after.x.size()) +
                                " particles (positions x, z); the same particles are needed");
  const std::vector<std::vector<int>> bonds =
      neighboursWithin(before.x, before.z, bond_cutoff, width, periodic_x);
  long total = 0, kept = 0;
  for (std::size_t j = 0; j < bonds.size(); ++j)
    for (int k : bonds[j]) {
      if (static_cast<std::size_t>(k) <= j) continue;  // each pair once
      double rx = after.x[j] - after.x[k];
      if (periodic_x) rx -= width * std::round(rx / width);
      ++total;
      kept += std::hypot(rx, after.z[j] - after.z[k]) <= broken_beyond;
    }
  return total > 0 ? static_cast<double>(kept) / static_cast<double>(total) : 1.0;
}

double meanRelativeDisplacement(const Snapshot& before, const Snapshot& after, double width,
                                bool periodic_x, double neighbour_cutoff) {
  const Displacements d = displacements(before, after, width, periodic_x);
  return relativeDisplacement(before, d, width, periodic_x, neighbour_cutoff);
}

StateResult classifyState(const std::vector<Snapshot>& cycles, double width, double diameter,
                          bool periodic_x, const StateOptions& opt) {
  const int K = static_cast<int>(cycles.size());
  if (K < 2)
    throw std::invalid_argument(
        "state classification needs snapshots from at least 2 consecutive cycles at one phase, "
        "got " +
        std::to_string(K));
  if (!(diameter > 0))
    throw std::invalid_argument("state classification: diameter must be positive");

  StateResult r;
  r.cycles = K;
  r.bonds_kept_per_cycle = 0;
  for (int c = 0; c + 1 < K; ++c) {
    const Displacements d = displacements(cycles[c], cycles[c + 1], width, periodic_x);
    r.mean_relative_displacement_d +=
        relativeDisplacement(cycles[c], d, width, periodic_x, opt.neighbour_cutoff * diameter) /
        diameter / (K - 1);
    r.mean_collective_displacement_d += std::hypot(d.mean_dx, d.mean_dz) / diameter / (K - 1);
    r.bonds_kept_per_cycle += bondsKept(cycles[c], cycles[c + 1], width, periodic_x,
                                        opt.bond_cutoff * diameter, opt.broken_beyond * diameter) /
                              (K - 1);
  }
  for (const Snapshot& s : cycles) {
    const HexaticOrder h = hexaticOrder(s.x, s.z, width, diameter, periodic_x, opt.hexatic);
    r.mean_abs_psi6 += h.mean_abs_psi6 / K;
    r.abs_mean_psi6 += h.abs_mean_psi6 / K;
  }
  r.bonds_kept = bondsKept(cycles.front(), cycles.back(), width, periodic_x,
                           opt.bond_cutoff * diameter, opt.broken_beyond * diameter);
  r.state =
      labelLayer(!(r.bonds_kept < opt.caged_fraction), r.mean_abs_psi6, opt.crystal_threshold);
  return r;
}

LayerState labelLayer(bool caged, double psi6, double crystal_threshold) {
  if (!caged) return LayerState::liquid_like;
  return psi6 > crystal_threshold ? LayerState::crystal : LayerState::amorphous;
}

}  // namespace granwave
