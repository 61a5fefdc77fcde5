// Cost against accuracy on the wet layer (docs/studies.md): the particles' statistical error
// against the cycles averaged, the hydro solver's discretisation error against its finest grid
// and tightest tolerance, and the model gap between the two that no grid removes.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "studies/contract/StudyResults.hpp"
#include "studies/method_comparison/MethodComparison.hpp"

namespace granwave {

// Particles: the statistical error against the cycles averaged. Hydro: the discretisation
// error against the finest grid with the tightest tolerance (the reference).
CostAccuracy costAccuracy(const MethodComparisonConfig& c, const RunSet& runs,
                          const Measurement& particles_front) {
  CostAccuracy out;
  for (double dur : c.cost_durations) {
    const std::string label =
        MethodComparisonConfig::particleRun(1, fmt::format("{} s", formatCompact(dur)));
    auto p = particleFields(runs, label);
    if (!p) continue;
    CostRow row;
    row.duration = dur;
    row.pooled_cycles = p->pooled_cycles;
    row.cpu = runs.get(label).cpu;
    row.speed = impactFronts(p->profiles).all;
    row.error = row.speed.error;
    out.ed_cpu.push_back(row.cpu);
    out.ed_error.push_back(row.error);
    out.rows.push_back(row);
  }
  const int ref_cells = *std::max_element(c.cost_cells.begin(), c.cost_cells.end());
  const double ref_rtol = *std::min_element(c.cost_rtol.begin(), c.cost_rtol.end());
  const HydroOutcome ref =
      hydroOutcome(runs, MethodComparisonConfig::costHydroRun(ref_cells, ref_rtol));
  const Measurement v_ref = ref.fields ? ref.fronts.all : Measurement{};
  for (int cells : c.cost_cells)
    for (double rtol : c.cost_rtol) {
      const HydroOutcome h = hydroOutcome(runs, MethodComparisonConfig::costHydroRun(cells, rtol));
      CostRow row;
      row.particles = false;
      row.ok = h.fields.has_value();
      row.reference = cells == ref_cells && rtol == ref_rtol;
      row.cells = cells;
      row.rtol = rtol;
      row.cpu = h.cpu;
      row.failure = h.failure;
      if (row.ok) {
        row.speed = h.fronts.all;
        row.error = row.reference ? NAN : std::abs(row.speed.value - v_ref.value);
        if (!row.reference && std::isfinite(row.error)) {
          out.hydro_by_rtol[rtol].first.push_back(row.cpu);
          out.hydro_by_rtol[rtol].second.push_back(row.error);
        }
      }
      out.rows.push_back(row);
    }
  out.model_gap = std::abs(v_ref.value - particles_front.value);
  return out;
}

void writeCostAccuracy(h5::File& f, const std::string& grp, const CostAccuracy& cost) {
  putSeries(f, grp + "/ed_cpu_seconds", cost.ed_cpu, "s");
  putSeries(f, grp + "/ed_error", cost.ed_error, "m s-1");
  for (const auto& [rtol, xy] : cost.hydro_by_rtol) {
    putSeries(f, fmt::format("{}/hydro_rtol_{:g}_cpu_seconds", grp, rtol), xy.first, "s");
    putSeries(f, fmt::format("{}/hydro_rtol_{:g}_error", grp, rtol), xy.second, "m s-1");
  }
  putValue(f, grp, "model_gap", cost.model_gap);
}

}  // namespace granwave
