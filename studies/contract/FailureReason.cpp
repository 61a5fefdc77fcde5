#include "studies/contract/FailureReason.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <exception>

namespace granwave {

// The collapse time in an engine's collapse message ("... collapse at t = 0.48 s: ..."), or
// NaN. Plain string search: std::regex draws warnings from libstdc++ in sanitizer builds.
double collapseTime(const std::string& message) {
  const std::string key = "collapse at t = ";
  const auto at = message.find(key);
  if (at == std::string::npos) return NAN;
  try {
    return std::stod(message.substr(at + key.size()));
  } catch (const std::exception&) {
    return NAN;
  }
}

// The solver's reason in a few words: the CVODE flag name if the message carries one.
std::string shortReason(const std::string& message) {
  const auto cv = message.find("CV_");
  if (cv != std::string::npos) {
    std::size_t end = cv + 3;
    while (end < message.size() &&
           (std::isupper(static_cast<unsigned char>(message[end])) || message[end] == '_'))
      ++end;
    return message.substr(cv, end - cv);
  }
  const double t = collapseTime(message);
  if (std::isfinite(t)) return fmt::format("collapse at t = {:.3f} s", t);
  // Else its first clause, cut between words (never inside one) and marked when cut.
  std::string clause = message.substr(0, message.find(" ("));
  constexpr std::size_t kLongest = 80;
  if (clause.size() <= kLongest) return clause;
  const auto space = clause.rfind(' ', kLongest);
  return clause.substr(0, space == std::string::npos ? kLongest : space) + " …";
}

}  // namespace granwave
