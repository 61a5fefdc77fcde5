#include "studies/runner/ExitCode.hpp"

namespace granwave {

bool isRunOutcome(int exit_code) {
  return exit_code >= kExitSuccess && exit_code <= kExitSolverFailure;
}

}  // namespace granwave
