#pragma once
// SIGINT/SIGTERM set a flag that the event loop polls at each record, so an interrupted
// run stops cleanly and saves what it has instead of dying mid-write.
#include <atomic>

namespace granwave {

// Installs the handlers (idempotent) and returns the flag they set.
const std::atomic<bool>& installInterruptFlag();

}  // namespace granwave
