#include "coarse_grain/FieldsAnalysis.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace granwave {

double FieldsAnalysis::plateHeight(int phase) const {
  return context.amplitude * std::sin(2 * std::numbers::pi * context.frequency * phaseTime(phase));
}

FieldsAnalysis analyseFields(const PhaseAverager& av, const FieldsContext& ctx,
                             const FrontOptions& fo, int min_count) {
  const PhaseAveragerConfig& c = av.config();
  if (av.firstPooledCycle() < 0 || av.pooledCycles() <= 0)
    throw std::runtime_error(
        "no steady cycles were pooled: the run is too short or never became steady "
        "(run longer, or give the number of cycles to discard)");
  FieldsAnalysis a;
  a.context = ctx;
  a.grid = c.grid;
  a.samples_per_cycle = c.samples_per_cycle;
  a.cycles_per_window = c.cycles_per_window;
  a.blocks = c.blocks;
  a.discarded_cycles = av.firstPooledCycle();
  a.pooled_cycles = av.pooledCycles();
  a.params = {ctx.mass, ctx.inertia, ctx.diameter, min_count};
  a.front_options = fo;
  a.pooled = computeFields(av.accumulator(), a.params);
  for (int b = 0; b < c.blocks; ++b)
    a.per_block.push_back(computeFields(av.accumulator(), a.params, b));
  a.front_height = frontHeights(a.pooled, c.grid.z0, c.grid.wz, ctx.T0, fo, &a.front_peak);
  std::vector<double> plate(a.pooled.phases);
  for (int ph = 0; ph < a.pooled.phases; ++ph) plate[ph] = a.plateHeight(ph);
  a.fronts = frontEpisodes(a.pooled, a.per_block, c.grid.z0, c.grid.wz, ctx.T0,
                           1.0 / (c.samples_per_cycle * ctx.frequency), fo, plate);
  return a;
}

}  // namespace granwave
