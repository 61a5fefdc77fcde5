#pragma once
// Normal coefficient of restitution e_n(v_n), v_n = |normal relative velocity| in m/s.
//   constant: e_n = e
//   dry:      e_n = 1 - kappa v_n^(1/5)      (Brilliantov & Poeschel leading order; paper Eq. 4),
//             clamped to [0, 1]
//   wet:      e_n = e_inf (1 - St_c / (q v_n)) for v_n >= v_c = St_c / q, else 0
//             (Mueller & Huang 2016; paper Eq. 5), q = rho_p d / (9 eta)
// A closed set of three laws evaluated on the hot path: a value type with a switch, not a
// virtual interface.
#include <algorithm>
#include <cmath>

namespace granwave {

class Restitution {
 public:
  enum class Law { Constant, Dry, Wet };

  static Restitution constant(double e) { return Restitution(Law::Constant, e, 0, 0); }
  static Restitution dry(double kappa) { return Restitution(Law::Dry, 0, kappa, 0); }
  // q in s/m (Stokes number St = q v_n); v_c = St_c / q.
  static Restitution wet(double e_inf, double stokes_critical, double q) {
    return Restitution(Law::Wet, e_inf, stokes_critical, q);
  }

  double operator()(double vn) const {
    switch (law_) {
      case Law::Constant:
        return a_;
      case Law::Dry:
        return std::clamp(1.0 - b_ * std::pow(vn, 0.2), 0.0, 1.0);
      case Law::Wet: {
        const double st = q_ * vn;
        return st >= b_ ? a_ * (1.0 - b_ / st) : 0.0;
      }
    }
    return a_;
  }

  Law law() const { return law_; }
  // Onset velocity below which a wet contact does not rebound (0 for the other laws).
  double onsetVelocity() const { return law_ == Law::Wet ? b_ / q_ : 0.0; }

 private:
  Restitution(Law law, double a, double b, double q) : law_(law), a_(a), b_(b), q_(q) {}
  Law law_;
  double a_;  // e (constant) or e_inf (wet)
  double b_;  // kappa (dry) or St_c (wet)
  double q_;  // wet only
};

}  // namespace granwave
