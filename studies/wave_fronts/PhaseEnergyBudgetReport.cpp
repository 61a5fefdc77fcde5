// The wave-fronts study's report on the layer's energy budget phase by phase (docs/studies.md,
// "Energy budget phase by phase"): where in the cycle the plate does its work and the layer
// loses it, particles beside the continuum.
#include <fmt/format.h>

#include <cmath>

#include "studies/wave_fronts/WaveFrontsReport.hpp"

namespace granwave {

namespace {

// Running sums of a series, in mJ, starting from 0 at the window's start.
std::vector<double> cumulativeMilli(const std::vector<double>& v) {
  std::vector<double> out;
  double s = 0;
  for (double x : v) out.push_back(1e3 * (s += x));
  return out;
}

std::vector<double> lossOf(const BudgetSeries& b) {
  std::vector<double> out;
  for (std::size_t k = 0; k < b.pair_loss.size(); ++k)
    out.push_back(b.pair_loss[k] + b.wall_loss[k]);
  return out;
}

Figure budgetFigure(const LawBudgets& lb, int law) {
  Figure fig;
  fig.title = fmt::format("Energy budget over the window, {} layer", kLawNames[law]);
  fig.xlabel = "t/T";
  fig.ylabel = "energy since the window's start (mJ, the paper's box)";
  fig.legend_outside = true;
  const std::pair<const BudgetSeries*, const char*> models[] = {
      {&lb.particles, "black"}, {&lb.smooth, "tab:purple"}, {&lb.rough, "tab:green"}};
  for (const auto& [b, colour] : models) {
    if (!b->valid()) continue;
    fig.series.push_back(
        lineSeries(b->phase, cumulativeMilli(b->work), b->model + ": plate work", colour));
    Series loss = lineSeries(b->phase, cumulativeMilli(lossOf(*b)), b->model + ": losses", colour);
    loss.linestyle = "--";
    fig.series.push_back(loss);
  }
  fig.caption =
      "Solid: the work the plate and lid have done on the layer since the window's start; "
      "dashed: the energy lost in pair collisions and at the walls. Particles: mean over the "
      "seeds' windows; continuum: its periodic window (2 cycles when it found none). Each point "
      "ends the interval it sums, so the first one holds the interval just before the window. In a "
      "periodic state the two "
      "meet at the window's end; where they part within it, the layer stores the difference "
      "as kinetic and potential energy.";
  return fig;
}

// mJ; the continuum's (exact) without an error, the particles' with the error's digits.
std::string perCycle(const Measurement& m) {
  if (!m.valid()) return "–";
  if (!(m.error > 0)) return fmt::format("{:.3f}", 1e3 * m.value);
  return format(Measurement{1e3 * m.value, 1e3 * m.error});
}

std::string share(const Measurement& part, const BudgetSeries& b) {
  const double total = b.pair_per_cycle.value + b.wall_per_cycle.value;
  if (!(total > 0)) return "–";
  return fmt::format("{:.1f} %", 100 * part.value / total);
}

}  // namespace

void energyBudgetSection(const WaveFrontsResults& r, Report& report) {
  ReportSection& s = report.section(
      "Energy budget phase by phase (paper's scene)",
      "The energy that crosses the layer over each phase interval: the work of the moving "
      "plate and lid, the loss in pair collisions (normal and tangential parts together: the "
      "particles' observables do not split them, the rough continuum's friction and rotation "
      "loss is counted here, and so is that of particles the resting-contact rule puts to rest) "
      "and "
      "the loss in collisions with the walls (plate, lid and side walls). Particles: the full "
      "model's "
      "fields over seeds; continuum: the velocity-dependent closure (Jenkins-Richman) for "
      "smooth disks and for rough particles, each with its budget integrated by CVODE beside "
      "the layer (docs/hydro.md, \"Energy budget\").");
  Table t;
  t.title = "Energy budget per drive cycle";
  t.caption = "mJ per cycle for the paper's box; particles: mean ± standard error over seeds.";
  t.columns = {"layer",
               "model",
               "seeds",
               "plate work (mJ)",
               "pair collisions (mJ)",
               "walls (mJ)",
               "walls' share of the loss",
               "work / the particles'"};
  for (int law = 0; law < kLaws; ++law) {
    const LawBudgets& lb = r.budgets[law];
    s.add(budgetFigure(lb, law));
    for (const BudgetSeries* b : {&lb.particles, &lb.smooth, &lb.rough}) {
      if (!b->valid()) {
        t.rows.push_back({kLawNames[law], b->model, "0", "none: " + b->why, "–", "–", "–", "–"});
        continue;
      }
      const double ratio =
          lb.particles.valid() ? b->work_per_cycle.value / lb.particles.work_per_cycle.value : NAN;
      t.rows.push_back({kLawNames[law], b->model,
                        b == &lb.particles ? std::to_string(b->seeds) : "–",
                        perCycle(b->work_per_cycle), perCycle(b->pair_per_cycle),
                        perCycle(b->wall_per_cycle), share(b->wall_per_cycle, *b),
                        std::isfinite(ratio) ? fmt::format("{:.2f}", ratio) : "–"});
    }
  }
  s.add(std::move(t));
}

}  // namespace granwave
