#pragma once
// The exit codes of all granwave commands (docs/commands.md), and which of them are the
// run's own outcome. A study caches a run's outcome (codes 0-4: the same scene and build give
// it again) but not a failure whose cause lies outside the run (a file that cannot be written,
// a checkpoint that cannot be used, an interrupt): that run is tried again next time
// (particle_run/OutsideFailure.hpp says which exceptions those are).
namespace granwave {

enum ExitCode : int {
  kExitSuccess = 0,
  kExitError = 1,             // e.g. a run that never became steady, an impossible initial state
  kExitInvalidInput = 2,      // scene, study file or command line
  kExitEngineBreakdown = 3,   // inelastic collapse or a stalled event loop
  kExitSolverFailure = 4,     // CVODE failed
  kExitOutOfMemory = 71,      // std::bad_alloc (sysexits EX_OSERR: the machine, not the input)
  kExitFileError = 74,        // HDF5 or file system (sysexits EX_IOERR)
  kExitCheckpointError = 75,  // checkpoint cannot be taken or used (sysexits EX_TEMPFAIL)
  kExitInterrupted = 130,
};

// True for the codes a study caches as the run's result.
bool isRunOutcome(int exit_code);

}  // namespace granwave
