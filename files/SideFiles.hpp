#pragma once
// The files granwave makes beside an output OUT while writing it, and may remove again:
//   OUT.tmp-PID, OUT.<anything>.tmp-PID  a temporary, renamed over its target when complete
//                                        (temporaryFor; a killed process's is removed later)
//   OUT.lock                             the lock of a checkpointed run
//   OUT.checkpoint, OUT.checkpoint-K.h5md  a checkpoint and its copy of the run file
//   OUT.interrupted                      the partial run file of an interrupted run
// A file the user names (a scene, an input, another output) must never be one of them: it
// would be removed or replaced. requireDistinct (OutputPath.hpp) refuses such names.
#include <string>

namespace granwave::files {

// What kind of side file of `output` the file `candidate` would be ("temporary", "lock
// file", "checkpoint", "checkpoint copy", "partial run file"), or nullptr if none. Both are
// compared by name in their directory (the directory's symbolic links resolved): removing a
// side file removes that name.
const char* sideFileKind(const std::string& candidate, const std::string& output);

// True if the file name `name` is a temporary "<prefix>.tmp-PID" or "<prefix>.<...>.tmp-PID";
// sets `pid` to the process it names.
bool isTemporaryOf(const std::string& name, const std::string& prefix, long& pid);

// True if the file name `name` is a checkpoint copy "<prefix>.checkpoint-K.h5md".
bool isCheckpointCopyOf(const std::string& name, const std::string& prefix);

}  // namespace granwave::files
