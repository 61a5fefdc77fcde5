// Which failures a study caches as the run's result (studies/ExitCode.hpp): the engine's and
// the solver's failures are; file and checkpoint problems, which come from outside the run,
// are not, and they keep a run's checkpoint.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "h5/H5Error.hpp"
#include "particles/EventLoopStall.hpp"
#include "particles/InelasticCollapse.hpp"
#include "studies/cli/OutsideFailure.hpp"
#include "studies/run_files/RunCheckpoint.hpp"
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

TEST(ExitCode, FileAndCheckpointErrorsComeFromOutsideTheRun) {
  EXPECT_TRUE(isOutsideFailure(CheckpointError("run.h5: another granwave process ...")));
  EXPECT_TRUE(isOutsideFailure(h5::H5Error("run.h5: write failed")));
  EXPECT_TRUE(isOutsideFailure(std::filesystem::filesystem_error(
      "rename", std::make_error_code(std::errc::no_space_on_device))));
  EXPECT_TRUE(isOutsideFailure(std::system_error(std::make_error_code(std::errc::io_error),
                                                 "f.xdmf: cannot write the XDMF sidecar")));
  EXPECT_TRUE(isOutsideFailure(std::bad_alloc()));
}

TEST(ExitCode, EngineBreakdownsAndAnalysisErrorsAreTheRunsOwn) {
  EXPECT_FALSE(isOutsideFailure(InelasticCollapse("collapse at t = 1 s", 1.0, 2, 3)));
  EXPECT_FALSE(isOutsideFailure(EventLoopStall("event loop stalled")));
  EXPECT_FALSE(isOutsideFailure(std::runtime_error("no steady cycles")));
}
