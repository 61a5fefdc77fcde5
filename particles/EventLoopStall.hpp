#pragma once
// Thrown when the event loop processes a huge number of events without the clock advancing
// (a bookkeeping cycle the engine cannot leave). Like InelasticCollapse it is a property of
// the scene and the build: the same run stalls again at the same event.
#include <stdexcept>
#include <string>

namespace granwave {

class EventLoopStall : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace granwave
