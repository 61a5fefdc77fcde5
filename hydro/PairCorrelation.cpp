#include "hydro/PairCorrelation.hpp"

namespace granwave::hydro {

double pairCorrelation(double nu) {
  const double h = 1.0 - nu;
  return (1.0 - 7.0 * nu / 16.0) / (h * h);
}

double pairCorrelationDerivative(double nu) {
  const double h = 1.0 - nu;
  return (25.0 - 7.0 * nu) / (16.0 * h * h * h);
}

}  // namespace granwave::hydro
