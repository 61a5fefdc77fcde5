#include "studies/runner/InterruptFlag.hpp"

#include <csignal>

namespace granwave {

namespace {
std::atomic<bool> g_interrupted{false};  // the one piece of process state a signal may touch
extern "C" void onSignal(int) { g_interrupted.store(true); }
}  // namespace

const std::atomic<bool>& installInterruptFlag() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  return g_interrupted;
}

}  // namespace granwave
