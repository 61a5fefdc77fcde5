// Which exit codes a study caches as the run's result (studies/runner/ExitCode.hpp): success
// and the run's own failures (the engine's, the solver's, bad input), not its surroundings'.
#include <gtest/gtest.h>

#include "studies/runner/ExitCode.hpp"

using namespace granwave;

TEST(ExitCode, RunOutcomesAreSuccessAndTheDeterministicFailuresOnly) {
  for (int code :
       {kExitSuccess, kExitError, kExitInvalidInput, kExitEngineBreakdown, kExitSolverFailure})
    EXPECT_TRUE(isRunOutcome(code)) << code;
  for (int code : {int{kExitOutOfMemory}, int{kExitFileError}, int{kExitCheckpointError},
                   int{kExitInterrupted}, 128 + 9, -1})
    EXPECT_FALSE(isRunOutcome(code)) << code;
}
