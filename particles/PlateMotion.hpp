#pragma once
// Sinusoidal drive of bottom and lid: z_b(t) = A sin(omega t), lid at z_b(t) + L_z
// (paper, Methods). Without drive A = omega = 0 and both walls are fixed.
#include <cmath>

namespace granwave {

// The plate's height and its time derivatives at one instant.
struct PlateState {
  double height = 0, velocity = 0, acceleration = 0, jerk = 0;
};

struct PlateMotion {
  double amplitude = 0;  // m
  double omega = 0;      // rad/s

  double height(double t) const { return amplitude * std::sin(omega * t); }
  double velocity(double t) const { return amplitude * omega * std::cos(omega * t); }
  double acceleration(double t) const { return -amplitude * omega * omega * std::sin(omega * t); }
  double jerk(double t) const { return -amplitude * omega * omega * omega * std::cos(omega * t); }
  double maxAcceleration() const { return amplitude * omega * omega; }
  // All four from one sine and cosine, each bit-identical to its function above.
  PlateState state(double t) const {
    const double s = std::sin(omega * t), c = std::cos(omega * t);
    return {amplitude * s, amplitude * omega * c, -amplitude * omega * omega * s,
            -amplitude * omega * omega * omega * c};
  }
};

}  // namespace granwave
