#pragma once
// An HDF5 file that appears at its target path only when complete. Writes go to
// "<target>.tmp-<pid>" in the same directory (so the final rename stays on one filesystem
// and is atomic); commit() flushes, closes, syncs and renames it over the target. Destroyed
// without commit (an exception, an interrupted run), it deletes the temporary: a crash or
// failure never leaves a file at the target that looks like a finished result.
#include <string>

#include "h5/File.hpp"

namespace granwave::h5 {

class AtomicFile {
 public:
  explicit AtomicFile(std::string target);
  // Continues a file saved by copyTo(): its bytes are copied to the temporary, which is
  // opened for appending (the saved copy itself stays untouched).
  AtomicFile(std::string target, const std::string& continue_from);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // The file being written; messages name the target, not the temporary.
  File& file() { return file_; }
  const std::string& target() const { return target_; }
  const std::string& temporaryPath() const { return temporary_; }
  bool committed() const { return committed_; }

  // Makes the file appear at target(). Closes the File (and every object open in it).
  void commit() { commitTo(target_); }
  // Same, at another path (e.g. "RUN.h5.interrupted"); must be on the target's filesystem.
  void commitTo(const std::string& path);
  // Flushes the file and publishes a copy of it, as it is now, at `path` (atomically; the
  // file stays open for writing). A checkpoint: HDF5 gives no guarantee for a file killed
  // while open, so a restart continues from this copy, not from the temporary.
  void copyTo(const std::string& path);

 private:
  std::string target_;
  std::string temporary_;
  File file_;
  bool committed_ = false;
};

}  // namespace granwave::h5
