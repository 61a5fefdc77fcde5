#pragma once
// Bridge from HDF5's error stack to H5Error. HDF5 prints a multi-screen trace to stderr by
// default; we switch that off and instead fold the innermost HDF5 message (the one closest to
// the cause, e.g. "truncated file: eof = ...") into the one-line H5Error.
#include <hdf5.h>

#include <string>

namespace granwave::h5 {

// Turns off HDF5's automatic error printing for the calling thread. Cheap; called by every
// File factory so no caller has to remember it.
void silenceHdf5Errors();

// Throws H5Error("<file>: <what> (<innermost HDF5 message>)"). Must be called right after the
// failing HDF5 call: the next HDF5 call clears the stack.
[[noreturn]] void fail(const std::string& file, const std::string& what);

// Throws via fail() when an HDF5 call returned a negative id or status.
inline hid_t check(hid_t id, const std::string& file, const std::string& what) {
  if (id < 0) fail(file, what);
  return id;
}

}  // namespace granwave::h5
