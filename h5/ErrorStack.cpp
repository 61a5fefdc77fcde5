#include "h5/ErrorStack.hpp"

#include "h5/H5Error.hpp"

namespace granwave::h5 {
namespace {

// Walking upward starts at the innermost function, where the error was detected; keep the first
// non-empty description, which names the cause rather than the API call that failed.
herr_t keepInnermost(unsigned n, const H5E_error2_t* err, void* out) {
  auto* message = static_cast<std::string*>(out);
  if (message->empty() && err->desc != nullptr && err->desc[0] != '\0') *message = err->desc;
  (void)n;
  return 0;
}

// HDF5's file drivers report a failed read or write as "file write failed: time = ...,
// filename = ..., errno = 28, error message = 'No space left on device', buf = 0x...": the
// cause is the quoted system message.
std::string systemCause(const std::string& message) {
  const std::string mark = "error message = '";
  const std::size_t at = message.find(mark);
  if (at == std::string::npos) return message;
  const std::size_t end = message.find('\'', at + mark.size());
  if (end == std::string::npos) return message;
  return message.substr(at + mark.size(), end - at - mark.size());
}

std::string innermostMessage() {
  std::string message;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keepInnermost, &message);
  H5Eclear2(H5E_DEFAULT);
  message = systemCause(message);
  for (char& c : message) {
    if (c == '\n' || c == '\r') c = ' ';  // the H5Error message stays one line
  }
  return message;
}

}  // namespace

void silenceHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void skipLibraryShutdownAtExit() { H5dont_atexit(); }

void fail(const std::string& file, const std::string& what) {
  const std::string detail = innermostMessage();
  std::string message = file + ": " + what;
  if (!detail.empty()) message += " (" + detail + ")";
  throw H5Error(message);
}

}  // namespace granwave::h5
