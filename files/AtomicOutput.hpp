#pragma once
// A file that appears at its target path only when complete, for writers that are not HDF5
// (h5/AtomicFile.hpp is the HDF5 one): the writer writes temporaryPath() (beside the target,
// temporaryFor), commit() syncs it to disk and renames it over the target, so a reader, a
// crash or a kill sees the old file or the whole new one. Destroyed without commit (an
// exception, a failed write), it removes the temporary.
#include <string>

namespace granwave::files {

class AtomicOutput {
 public:
  // PathError (OutputPath.hpp) unless the target is a regular file or a new name.
  explicit AtomicOutput(std::string target);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::string& target() const { return target_; }
  const std::string& temporaryPath() const { return temporary_; }

  // The temporary, complete and closed by its writer, made the target. std::system_error
  // naming the target if it cannot be synced or renamed (the temporary is then removed).
  void commit();

 private:
  std::string target_;
  std::string temporary_;
  bool committed_ = false;
};

}  // namespace granwave::files
