#include "coarse_grain/FieldsAnalysis.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace granwave {

double FieldsAnalysis::plateHeight(int phase) const {
  return context.amplitude * std::sin(2 * std::numbers::pi * context.frequency * phaseTime(phase));
}

PhaseProfiles FieldsAnalysis::profiles() const {
  PhaseProfiles p;
  for (int j = 0; j < pooled.nz; ++j) p.z.push_back(grid.zCentre(j));
  for (int k = 0; k < pooled.phases; ++k) {
    p.time.push_back(phaseTime(k));
    p.phase.push_back(static_cast<double>(k) / samples_per_cycle);  // 0 .. cycles_per_window
    p.plate_height.push_back(plateHeight(k));
  }
  p.front_height = front_height;
  p.front_peak_temperature = front_peak;
  p.pooled = profilesOf(pooled);
  for (const PhaseFields& b : per_block) p.blocks.push_back(profilesOf(b));
  p.fronts = fronts;
  return p;
}

FieldsAnalysis analyseFields(const PhaseAverager& av, const FieldsContext& ctx,
                             const FrontOptions& fo, int min_count) {
  if (av.firstPooledCycle() < 0 || av.pooledCycles() <= 0)
    throw std::runtime_error(
        "no steady cycles were pooled: the run is too short or never became steady "
        "(run longer, or give the number of cycles to discard)");
  return analyseAccumulated(av.accumulator(), av.config(), av.firstPooledCycle(), av.pooledCycles(),
                            ctx, fo, min_count);
}

FieldsAnalysis analyseAccumulated(const PhaseAccumulator& acc, const PhaseAveragerConfig& c,
                                  int discarded, int pooled, const FieldsContext& ctx,
                                  const FrontOptions& fo, int min_count) {
  FieldsAnalysis a;
  a.context = ctx;
  a.grid = c.grid;
  a.samples_per_cycle = c.samples_per_cycle;
  a.cycles_per_window = c.cycles_per_window;
  a.blocks = c.blocks;
  a.discarded_cycles = discarded;
  a.pooled_cycles = pooled;
  a.params = {ctx.mass, ctx.inertia, ctx.diameter, min_count};
  a.front_options = fo;
  a.pooled = computeFields(acc, a.params);
  for (int b = 0; b < c.blocks; ++b) a.per_block.push_back(computeFields(acc, a.params, b));
  a.front_height = frontHeights(a.pooled, c.grid.z0, c.grid.wz, ctx.T0, fo, &a.front_peak);
  std::vector<double> plate(a.pooled.phases);
  for (int ph = 0; ph < a.pooled.phases; ++ph) plate[ph] = a.plateHeight(ph);
  a.fronts = frontEpisodes(a.pooled, a.per_block, c.grid.z0, c.grid.wz, ctx.T0,
                           1.0 / (c.samples_per_cycle * ctx.frequency), fo, plate);
  return a;
}

void addStateFields(FieldsAnalysis& a, const StatePhaseAverager& st) {
  a.states.clear();
  for (int period = 1; period <= 2; ++period) {
    a.state_windows[period - 1] = st.windows(period);
    // Every block needs a window of its own for the per-block errors.
    if (st.windows(period) < st.config().blocks) continue;
    FieldsAnalysis s =
        analyseAccumulated(st.accumulator(period), st.config(), st.firstWindowCycle(),
                           st.pooledCycles(period), a.context, a.front_options, a.params.min_count);
    s.state_period = period;
    a.states.push_back(std::move(s));
  }
}

}  // namespace granwave
