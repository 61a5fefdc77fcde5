#pragma once
// Which exceptions come from a run's surroundings rather than its physics or input: a study
// does not cache such a run (runner/ExitCode.hpp, code 74 or 75), and a particle run keeps its
// checkpoint for the next attempt.
#include <exception>

namespace granwave {

// True if `e` did not come from the run's physics or input but from its surroundings (files,
// disk, a held lock, a damaged checkpoint): a checkpoint stays for the next attempt.
bool isOutsideFailure(const std::exception& e);

}  // namespace granwave
