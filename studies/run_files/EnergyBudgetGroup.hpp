#pragma once
// The /budget group of the 1D and the 2D hydro run files (docs/hydro.md, "Energy budget"):
// the energy that crossed the layer over each phase interval of the run's window, in J of the
// scene's box (the 1D continuum's J per unit width times the box's width; the 2D continuum's
// energies are the box's already, width 1). One owner for both files' layout: HydroRunFile
// and Hydro2DRunFile write it through here.
#include <vector>

#include "h5/File.hpp"

namespace granwave {

struct RunEnergyBudget {
  std::vector<double> plate_work, collisional_loss, friction_loss, wall_loss, energy_change;
  bool empty() const { return plate_work.empty(); }
  // Appends one phase interval's terms times `width` (hydro::PhaseBudget's order: plate work,
  // collisional, friction, wall and side-wall loss, energy change); the side walls' loss is
  // counted with the wall loss.
  void addPhase(double width, double work, double collisional, double friction, double wall,
                double side_wall, double change);
  // Summed over the window per drive cycle, in mJ: plate work, the three losses, the energy
  // change, and the closure change - (work - losses).
  struct PerCycle {
    double work, pair, friction, wall, change, closure;
    double lost() const { return pair + friction + wall; }
  };
  PerCycle perCycle(int window_cycles) const;
};

// Writes /budget (nothing when the budget is empty).
void writeEnergyBudget(h5::File& f, const RunEnergyBudget& b);
// Reads /budget, empty when the file has none.
RunEnergyBudget readEnergyBudget(const h5::File& f);

}  // namespace granwave
