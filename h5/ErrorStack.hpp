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

// Called first in main, before any other HDF5 call: the library installs no exit handler. A
// file whose last flush fails (a full disk) cannot be closed: HDF5 keeps it open, and its own
// shutdown at exit would flush it again and crash (SIGSEGV in H5F__close_cb, HDF5 1.10). The
// program closes (or, failing that, discards and removes) every file it opened itself, so
// nothing is lost when the library is not shut down.
void skipLibraryShutdownAtExit();

// Throws H5Error("<file>: <what> (<innermost HDF5 message>)"). For a failed system call the
// message is its errno text alone ("No space left on device"), not HDF5's whole report. Must be
// called right after the failing HDF5 call: the next HDF5 call clears the stack.
[[noreturn]] void fail(const std::string& file, const std::string& what);

// Throws via fail() when an HDF5 call returned a negative id or status.
inline hid_t check(hid_t id, const std::string& file, const std::string& what) {
  if (id < 0) fail(file, what);
  return id;
}

}  // namespace granwave::h5
