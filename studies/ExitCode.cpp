#include "studies/ExitCode.hpp"

#include <filesystem>

#include "h5/H5Error.hpp"
#include "studies/RunCheckpoint.hpp"

namespace granwave {

bool isRunOutcome(int exit_code) {
  return exit_code >= kExitSuccess && exit_code <= kExitSolverFailure;
}

bool isOutsideFailure(const std::exception& e) {
  return dynamic_cast<const CheckpointError*>(&e) || dynamic_cast<const h5::H5Error*>(&e) ||
         dynamic_cast<const std::filesystem::filesystem_error*>(&e);
}

}  // namespace granwave
