#pragma once
// Pair correlation of hard disks at contact (physics-hydro.md 1.2), Henderson (1975),
// Mol. Phys. 30, 971:
//
//     Z = p A / (N T) = (1 + nu^2/8) / (1 - nu)^2
//     g2(nu) = (Z - 1) / (2 nu) = (1 - 7 nu/16) / (1 - nu)^2
//     dg2/dnu = (25 - 7 nu) / (16 (1 - nu)^3)
//
// nu = n pi sigma^2 / 4 is the area fraction. g2 is finite up to nu = 1 (at hexagonal close
// packing nu = pi/(2 sqrt 3) = 0.9069 it is 69.5) and is not meant beyond close packing.

namespace granwave::hydro {

// Henderson g2(nu), 0 <= nu < 1.
double pairCorrelation(double nu);

// dg2/dnu of the Henderson form, 0 <= nu < 1.
double pairCorrelationDerivative(double nu);

}  // namespace granwave::hydro
