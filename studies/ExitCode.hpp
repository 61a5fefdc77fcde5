#pragma once
// The exit codes of all granwave commands (docs/commands.md), and which failures are the
// run's own outcome. A study caches a run's outcome (codes 0-4: the same scene and build give
// it again) but not a failure whose cause lies outside the run (a file that cannot be written,
// a checkpoint that cannot be used, an interrupt): that run is tried again next time.
#include <exception>

namespace granwave {

enum ExitCode : int {
  kExitSuccess = 0,
  kExitError = 1,             // e.g. a run that never became steady, an impossible initial state
  kExitInvalidInput = 2,      // scene, study file or command line
  kExitEngineBreakdown = 3,   // inelastic collapse or a stalled event loop
  kExitSolverFailure = 4,     // CVODE failed
  kExitFileError = 74,        // HDF5 or file system (sysexits EX_IOERR)
  kExitCheckpointError = 75,  // checkpoint cannot be taken or used (sysexits EX_TEMPFAIL)
  kExitInterrupted = 130,
};

// True for the codes a study caches as the run's result.
bool isRunOutcome(int exit_code);
// True if `e` did not come from the run's physics or input but from its surroundings (files,
// disk, a held lock, a damaged checkpoint): a checkpoint stays for the next attempt.
bool isOutsideFailure(const std::exception& e);

}  // namespace granwave
