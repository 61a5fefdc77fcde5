#include "coarse_grain/WithinCycleState.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

struct CycleLabel {
  LayerState state = LayerState::amorphous;
  double coordination = 0, psi6 = 0;
  int compact_phase = 0;
  int lid_row = 0;
};

int onLid(const Snapshot& s, double lid, double diameter, double gap) {
  int n = 0;
  for (double z : s.z) n += z + 0.5 * diameter >= lid - gap;
  return n;
}

CycleLabel labelCycle(const std::vector<Snapshot>& phases, double width, double height,
                      double diameter, bool periodic_x, const WithinCycleOptions& opt) {
  CycleLabel c;
  c.coordination = -1;
  for (std::size_t k = 0; k < phases.size(); ++k) {
    const Snapshot& s = phases[k];
    const double z = meanCoordination(s, opt.neighbour_cutoff * diameter, width, periodic_x);
    if (z > c.coordination) {
      c.coordination = z;
      c.compact_phase = static_cast<int>(k);
    }
    c.lid_row =
        std::max(c.lid_row, onLid(s, s.plate_height + height, diameter, opt.lid_gap * diameter));
  }
  const Snapshot& densest = phases[static_cast<std::size_t>(c.compact_phase)];
  c.psi6 =
      hexaticOrder(densest.x, densest.z, width, diameter, periodic_x, opt.hexatic).mean_abs_psi6;
  c.state = labelLayer(!(c.coordination < opt.caged_coordination), c.psi6, opt.crystal_threshold);
  return c;
}

}  // namespace

double meanCoordination(const Snapshot& s, double cutoff, double width, bool periodic_x) {
  if (s.x.empty()) return 0;
  const std::vector<std::vector<int>> nb = neighboursWithin(s.x, s.z, cutoff, width, periodic_x);
  double bonds = 0;
  for (const auto& n : nb) bonds += static_cast<double>(n.size());
  return bonds / static_cast<double>(s.x.size());
}

WithinCycleResult classifyWithinCycles(const std::vector<std::vector<Snapshot>>& cycles,
                                       double width, double height, double diameter,
                                       bool periodic_x, const WithinCycleOptions& opt) {
  if (cycles.empty() || cycles.front().empty())
    throw std::invalid_argument(
        "within-cycle classification needs at least one cycle of sampled phases");
  if (!(diameter > 0))
    throw std::invalid_argument("within-cycle classification: diameter must be positive");
  const std::size_t S = cycles.front().size();
  const int K = static_cast<int>(cycles.size());
  WithinCycleResult r;
  r.cycles = K;
  std::array<int, 3> votes{};  // crystal, amorphous, liquid-like
  std::vector<int> phase_votes(S, 0);
  for (const auto& phases : cycles) {
    if (phases.size() != S)
      throw std::invalid_argument("within-cycle classification: cycles hold " + std::to_string(S) +
                                  " and " + std::to_string(phases.size()) +
                                  " sampled phases; every cycle needs the same phases");
    const CycleLabel c = labelCycle(phases, width, height, diameter, periodic_x, opt);
    ++votes[static_cast<std::size_t>(c.state)];
    ++phase_votes[static_cast<std::size_t>(c.compact_phase)];
    r.coordination += c.coordination / K;
    r.psi6 += c.psi6 / K;
    r.lid_row += static_cast<double>(c.lid_row) / K;
    r.lid_row_cycles += (c.lid_row > 0 ? 1.0 : 0.0) / K;
  }
  r.crystal_share = static_cast<double>(votes[0]) / K;
  r.amorphous_share = static_cast<double>(votes[1]) / K;
  r.liquid_share = static_cast<double>(votes[2]) / K;
  std::size_t best = 0;  // ties: the first of crystal, amorphous, liquid-like
  for (std::size_t i = 1; i < votes.size(); ++i)
    if (votes[i] > votes[best]) best = i;
  r.state = static_cast<LayerState>(best);
  std::size_t phase = 0;
  for (std::size_t k = 1; k < S; ++k)
    if (phase_votes[k] > phase_votes[phase]) phase = k;
  r.compact_phase = static_cast<double>(phase) / static_cast<double>(S);
  return r;
}

}  // namespace granwave
