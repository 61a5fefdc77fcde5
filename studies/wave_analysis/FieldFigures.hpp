#pragma once
// Figures drawn from phase-resolved profiles (particles or hydro) that several studies share:
// the density space-time plot with fronts, centre of mass and plates (the paper's Fig. 5), and
// profiles at chosen phases (Figs. 4b, 7).
#include <string>
#include <vector>

#include "coarse_grain/PhaseProfiles.hpp"
#include "studies/report/Report.hpp"

namespace granwave {

// Area fraction over t/T (x) and z/d (y), with the front heights, the centre of mass, the
// plate and the lid (plate + container height) drawn on it.
Figure spaceTimeFigure(const PhaseProfiles& p, double diameter, double container_height,
                       std::string title, std::string caption);

// One line per phase: field(z) * scale against z/d, at the phases `phases` (t/T within the
// window; each taken at the nearest sampled phase, labelled by its t/T within its cycle).
Figure profilesAtPhases(const PhaseProfiles& p, const std::vector<double>& field, double scale,
                        double diameter, const std::vector<double>& phases, std::string title,
                        std::string ylabel, std::string caption);

// Centre-of-mass height (relative to the mean plate position, in d) over the window.
Series centerOfMassSeries(const PhaseProfiles& p, double diameter, std::string label,
                          std::string color = "");

}  // namespace granwave
