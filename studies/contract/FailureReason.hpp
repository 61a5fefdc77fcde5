#pragma once
// A failed run's one-line reason, shortened for a table cell: the CVODE flag of a hydro
// failure (CV_CONSTR_FAIL, ...), the time of an inelastic collapse, else the message's first
// clause (up to " ("), cut between words after 80 characters.
#include <string>

namespace granwave {

std::string shortReason(const std::string& message);
// The collapse time in an engine's collapse message ("... collapse at t = 0.48 s: ..."), or NaN.
double collapseTime(const std::string& message);

}  // namespace granwave
