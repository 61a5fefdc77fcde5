#pragma once
// Sound speeds of the granular gas of disks, d = 2 (docs/hydro.md, "Theory helpers").
//
// Equation of state p = n T F(nu, theta), with the compressibility factor
//
//     F(nu, theta) = p / (n T) = 1 + Phi_P(theta) nu g2(nu)       (Phi_P = 1 + e for constant e)
//
// and internal energy (d/2) T per particle. Along an isentrope, without collisional loss over a
// wave period, dT/dn|_s = 2p/(d n^2), so
//
//     c_s^2 = (1/m) [ dp/dn|_T + (2p/(d n^2)) dp/dT|_n ]
//           = theta [ F + nu dF/dnu + (2/d) F (F + theta dF/dtheta) ]        (adiabatic)
//     c_T^2 = theta [ F + nu dF/dnu ]                                       (isothermal)
//
// with dF/dnu = Phi_P (g2 + nu g2') and theta dF/dtheta = theta Phi_P'(theta) nu g2 (zero for
// constant e, where c_s^2 = theta [F + nu F' + (2/d) F^2]). Dilute limit: c_s^2 = 2 theta
// (gamma = 2), c_T^2 = theta.
#include "hydro/RestitutionClosure.hpp"

namespace granwave::hydro {

// F(nu, theta) = 1 + Phi_P(theta) nu g2(nu).
double pressureFactor(double nu, double theta, const RestitutionClosure& restitution);

// c_s in m/s at area fraction 0 <= nu < 1 and theta >= 0 (m^2/s^2).
double adiabaticSoundSpeed(double nu, double theta, const RestitutionClosure& restitution);
// c_T in m/s.
double isothermalSoundSpeed(double nu, double theta, const RestitutionClosure& restitution);

}  // namespace granwave::hydro
