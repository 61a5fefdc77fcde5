#pragma once
// What every granwave command checks about the files it is given, before any work starts:
// an output is a regular file or a new name in an existing directory (never a device, a
// FIFO, a directory: renaming over those would replace them), an input is a regular file (a
// FIFO would block the command, a device would be read forever), and no output is the same
// file as an input or as another output (a run file must not replace its own scene). Same
// file means the same device and inode where the file exists, the same normalised absolute
// path (symbolic links of the existing part resolved) otherwise.
#include <stdexcept>
#include <string>
#include <vector>

namespace granwave::files {

// A path a command refuses; the message is one line naming the path and what is valid.
class PathError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A file a command names, with its role for the messages ("run file", "fields sidecar").
// `derived` marks a file the command makes from another one it names (a checkpoint, a
// partial run file): checked as an output, but it may be a side file (SideFiles.hpp).
struct NamedPath {
  std::string role;
  std::string path;
  bool derived = false;
};

// PathError unless `path` names a regular file or a new name in an existing directory that
// this process may write in, short enough to take the temporary's suffix.
void requireOutputPath(const std::string& path);
// PathError unless `path` names a directory this process may write in, or a new name whose
// nearest existing ancestor is one (so creating it cannot fail half way); `option` names the
// option for the message ("-o", "--cache").
void requireOutputDirectory(const std::string& path, const std::string& option);
// PathError unless `path` names an existing regular file (symbolic links followed).
void requireInputFile(const std::string& path);
// PathError if two of the files are the same file and at least one of them is an output
// (two inputs may well be one file), or if a file named (not derived) is a side file of an
// output (SideFiles.hpp). Also checks every output with requireOutputPath.
void requireDistinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);
// True if the two paths name the same file (existing or not), as described above.
bool sameFile(const std::string& a, const std::string& b);

// The temporary a file is written to before it is renamed over `target`: in the target's
// directory (so the rename stays on one file system and is atomic), named for this process
// ("<target>.tmp-<pid>", the form studies/runner/OrphanedTemporaries recognises).
std::string temporaryFor(const std::string& target);

}  // namespace granwave::files
