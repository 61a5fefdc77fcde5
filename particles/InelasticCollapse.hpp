#pragma once
// Thrown when the collision rate of a particle diverges (inelastic collapse: McNamara &
// Young 1994), typically because the TC model is off. The message names the time, the
// particles and the remedy.
#include <stdexcept>
#include <string>

namespace granwave {

class InelasticCollapse : public std::runtime_error {
 public:
  InelasticCollapse(const std::string& what, double time, int particle, int partner)
      : std::runtime_error(what), time_(time), particle_(particle), partner_(partner) {}
  double time() const { return time_; }
  int particle() const { return particle_; }
  int partner() const { return partner_; }

 private:
  double time_;
  int particle_;
  int partner_;
};

}  // namespace granwave
