// Which failures come from a run's surroundings (studies/particle_run/OutsideFailure.hpp): file
// and checkpoint problems and this machine's memory are, and a run keeps its checkpoint for
// them (a study does not cache them); the engine's breakdowns and the analysis's errors are the
// run's own result.
#include <gtest/gtest.h>

#include <filesystem>
#include <new>
#include <stdexcept>
#include <system_error>

#include "h5/H5Error.hpp"
#include "particles/EventLoopStall.hpp"
#include "particles/InelasticCollapse.hpp"
#include "studies/particle_run/OutsideFailure.hpp"
#include "studies/run_files/RunCheckpoint.hpp"

using namespace granwave;

TEST(OutsideFailure, FileAndCheckpointErrorsComeFromOutsideTheRun) {
  EXPECT_TRUE(isOutsideFailure(CheckpointError("run.h5: another granwave process ...")));
  EXPECT_TRUE(isOutsideFailure(h5::H5Error("run.h5: write failed")));
  EXPECT_TRUE(isOutsideFailure(std::filesystem::filesystem_error(
      "rename", std::make_error_code(std::errc::no_space_on_device))));
  EXPECT_TRUE(isOutsideFailure(std::system_error(std::make_error_code(std::errc::io_error),
                                                 "f.xdmf: cannot write the XDMF sidecar")));
  EXPECT_TRUE(isOutsideFailure(std::bad_alloc()));
}

TEST(OutsideFailure, EngineBreakdownsAndAnalysisErrorsAreTheRunsOwn) {
  EXPECT_FALSE(isOutsideFailure(InelasticCollapse("collapse at t = 1 s", 1.0, 2, 3)));
  EXPECT_FALSE(isOutsideFailure(EventLoopStall("event loop stalled")));
  EXPECT_FALSE(isOutsideFailure(std::runtime_error("no steady cycles")));
}
