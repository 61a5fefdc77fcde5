#pragma once
// Sinusoidal drive of bottom and lid: z_b(t) = A sin(omega t), lid at z_b(t) + L_z
// (paper, Methods). Without drive A = omega = 0 and both walls are fixed.
#include <cmath>

namespace granwave {

struct PlateMotion {
  double amplitude = 0;  // m
  double omega = 0;      // rad/s

  double height(double t) const { return amplitude * std::sin(omega * t); }
  double velocity(double t) const { return amplitude * omega * std::cos(omega * t); }
  double acceleration(double t) const { return -amplitude * omega * omega * std::sin(omega * t); }
  double jerk(double t) const { return -amplitude * omega * omega * omega * std::cos(omega * t); }
  double maxAcceleration() const { return amplitude * omega * omega; }
};

}  // namespace granwave
