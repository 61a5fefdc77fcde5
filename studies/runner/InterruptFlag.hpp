#pragma once
// SIGINT/SIGTERM set a flag that the event loop polls at each record, so an interrupted
// run stops cleanly and saves what it has instead of dying mid-write.
#include <atomic>
#include <stdexcept>

namespace granwave {

// A command stopped by SIGINT/SIGTERM before its output was complete (exit 130): nothing of
// the output is left.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Installs the handlers (idempotent) and returns the flag they set.
const std::atomic<bool>& installInterruptFlag();

}  // namespace granwave
