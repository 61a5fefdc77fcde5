#pragma once
// Starting the write-back of an open HDF5 file's dirty pages without waiting for it
// (sync_file_range(2)), so that a later fsync (a commit, an interrupt) waits only for what was
// written since, however large the file has grown.
#include "h5/File.hpp"

namespace granwave::h5 {

// A no-op for drivers other than the default POSIX one (sec2), and where it fails: the
// commit's fsync still reports what matters.
void startWriteback(const File& file);

}  // namespace granwave::h5
