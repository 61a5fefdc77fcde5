#include "hydro/PairCorrelation.hpp"

namespace granwave::hydro {

double pairCorrelation(double nu) { return detail::hendersonG2(nu); }

double pairCorrelationDerivative(double nu) { return detail::hendersonDG2(nu); }

}  // namespace granwave::hydro
