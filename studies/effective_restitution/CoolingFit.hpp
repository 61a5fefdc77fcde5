#pragma once
// Effective restitution from free cooling (Haff's law) of a homogeneous gas of disks.
// Kinetic theory (Haff, J. Fluid Mech. 134, 401 (1983); Enskog cooling rate of inelastic
// disks, e.g. Brilliantov & Poeschel, Kinetic Theory of Granular Gases (2004), ch. 6;
// hydro/TransportCoefficients.hpp) gives
//     d theta / dt = -zeta theta,   zeta = sqrt(pi) Phi_W(theta) g2(nu) n sigma sqrt(theta),
// so for a constant Phi_W = 1 - e^2, theta^{-1/2} grows linearly in time with slope
//     s = (1/2) sqrt(pi) Phi_W g2(nu) n sigma.
// A straight-line fit of theta^{-1/2}(t) over the samples with theta in [lo, hi] gives
// Phi_W and e_eff = sqrt(1 - Phi_W) for that temperature range; a velocity-dependent law shows
// up as e_eff changing from one range to the next.
#include <vector>

#include "studies/statistics/Measurement.hpp"

namespace granwave {

struct CoolingFit {
  double theta = 0;                      // geometric mean of the samples in range, m^2/s^2
  double theta_low = 0, theta_high = 0;  // the range
  int samples = 0;
  Measurement phi_w;  // <1 - e^2>
  Measurement e_eff;
};

// theta [sample] = translational kinetic energy / (N m) at times t [sample] (s). nu: area
// fraction, n: number density (1/m^2), sigma: diameter (m). Error: the least-squares standard
// error of the slope. Needs at least 4 samples in range; otherwise phi_w is invalid.
CoolingFit fitCooling(const std::vector<double>& t, const std::vector<double>& theta, double nu,
                      double n, double sigma, double lo, double hi);

// Fits over `bins` logarithmic temperature ranges between lo and hi (highest first).
std::vector<CoolingFit> fitCoolingByTemperature(const std::vector<double>& t,
                                                const std::vector<double>& theta, double nu,
                                                double n, double sigma, double lo, double hi,
                                                int bins);

}  // namespace granwave
