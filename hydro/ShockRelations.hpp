#pragma once
// Rankine-Hugoniot relations for a granular gas of disks, d = 2 (docs/hydro.md, "Theory helpers"),
// dissipation inside the shock neglected. Upstream state 1 at rest, a piston (the plate)
// driving the gas at speed U_p > 0 into it, shock speed s in the upstream frame:
//
//     mass:      rho1 s = rho2 (s - U_p)
//     momentum:  p2 - p1 = rho1 s U_p
//     energy:    (d/2)(theta2 - theta1) = (1/2)(p1 + p2)(1/rho1 - 1/rho2)      (Hugoniot)
//
// with p = rho theta F(nu, theta), F = 1 + Phi_P(theta) nu g2(nu) (SoundSpeed.hpp); m and sigma
// drop out (rho = m n, nu = n pi sigma^2 / 4).
//
// General solver. Mass and momentum give the Rayleigh line U_p^2 = (p2 - p1)(1/rho1 - 1/rho2);
// subtracting it from the Hugoniot gives theta2 explicitly in terms of nu2,
//
//     theta2(nu2) = theta1 + (2/d) [ theta1 F1 (1 - nu1/nu2) + U_p^2 / 2 ],
//
// leaving one equation for r = nu2/nu1 > 1,
//
//     H(nu2) = (theta2 F2 - theta1 F1 / r)(r - 1) - U_p^2 = 0,    F2 = F(nu2, theta2(nu2)).
//
// H(nu1) = -U_p^2 < 0 and H -> +inf as nu2 -> 1 (Henderson g2 diverges), and H increases with
// nu2 whenever theta F(nu, theta) increases with theta (all three laws at physical
// parameters), so the root is unique; it is found by bracketing (Brent) on (nu1, 1).
// Then s = U_p nu2 / (nu2 - nu1).
//
// Strong shock into a cold layer (theta1 -> 0), any EOS:
//
//     theta2 = U_p^2 / d,   nu1 / (nu2 - nu1) = F(nu2, theta2) / d,   s = U_p [1 + F(nu2)/d].
//
// Dilute ideal gas, gamma = (d + 2)/d = 2, upstream Mach number M = s / c1, c1^2 = 2 theta1:
//
//     rho2/rho1 = (gamma + 1) M^2 / ((gamma - 1) M^2 + 2),
//     p2/p1     = (2 gamma M^2 - (gamma - 1)) / (gamma + 1),
//     s         = (gamma + 1) U_p / 4 + sqrt(((gamma + 1) U_p / 4)^2 + c1^2)    (piston)
//
// Late-time compaction (snow-plough) front, once the shocked gas has cooled to nu_max:
//     s = U_p nu_max / (nu_max - nu1).
//
// Henderson's g2 is finite up to nu = 1, so nu2 beyond close packing (0.9069) is returned as
// computed: the gas-dynamic relations are then outside their validity.
#include <numbers>

#include "hydro/PairCorrelation.hpp"
#include "hydro/RestitutionClosure.hpp"

namespace granwave::hydro {

inline constexpr double kRandomClosePacking2D =
    0.82;  // random close packing of disks (Torquato, PRE 51, 3170 (1995))

// A uniform state at rest: area fraction and theta (m^2/s^2).
struct GasState {
  double nu = 0;
  double theta = 0;
};

struct ShockSolution {
  double nu = 0;     // downstream area fraction nu2
  double theta = 0;  // downstream theta2, m^2/s^2
  double speed = 0;  // shock speed s relative to the upstream gas, m/s
  double mach = 0;   // s / c_s(upstream); +inf for a cold upstream
};

// Strong shock into a cold layer: 0 < nu1 < 1, U_p > 0 (m/s). Phi_P at theta2 = U_p^2/2.
ShockSolution strongShock(double nu1, double piston_speed, const RestitutionClosure& restitution);

// Finite upstream temperature: 0 < nu1 < 1, theta1 >= 0, U_p > 0.
ShockSolution rankineHugoniot(const GasState& upstream, double piston_speed,
                              const RestitutionClosure& restitution);

// Relative residuals of the three jump conditions for a computed downstream state:
// mass / (rho1 s), momentum / (rho1 s U_p), energy / ((d/2) theta2).
struct JumpResiduals {
  double mass = 0, momentum = 0, energy = 0;
};
JumpResiduals jumpResiduals(const GasState& upstream, const ShockSolution& downstream,
                            double piston_speed, const RestitutionClosure& restitution);

// Dilute ideal gas, gamma = 2.
double idealGasDensityRatio(double mach);   // rho2/rho1 = 3 M^2 / (M^2 + 2)
double idealGasPressureRatio(double mach);  // p2/p1 = (4 M^2 - 1) / 3
struct IdealGasShock {
  double speed = 0;              // s, m/s
  double mach = 0;               // s / sqrt(2 theta1) (+inf for theta1 = 0)
  double density_ratio = 0;      // rho2/rho1 -> 3 for a strong shock
  double pressure_ratio = 0;     // p2/p1 (+inf for theta1 = 0)
  double temperature_ratio = 0;  // theta2/theta1 (+inf for theta1 = 0)
  double theta = 0;              // theta2, m^2/s^2
};
// Piston at U_p > 0 into an ideal gas at rest with theta1 >= 0.
IdealGasShock idealGasPistonShock(double theta1, double piston_speed);

// s = U_p nu_max / (nu_max - nu1), 0 <= nu1 < nu_max.
double compactionFrontSpeed(double nu1, double piston_speed,
                            double nu_max = kHexagonalClosePacking);

}  // namespace granwave::hydro
