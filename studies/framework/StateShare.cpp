#include "studies/framework/StateShare.hpp"

#include <algorithm>
#include <cmath>

#include "coarse_grain/PeriodDoublingSeries.hpp"

namespace granwave {

StateShare pooledStateShare(int windows, int period2_windows, double effective_windows) {
  StateShare s;
  if (windows <= 0) return s;
  s.share = static_cast<double>(period2_windows) / windows;
  s.effective_windows = std::max(1.0, effective_windows);
  wilsonInterval(s.share, s.effective_windows, s.low, s.high);
  return s;
}

StateShare exactStateShare(int period) {
  StateShare s;
  if (period != 1 && period != 2) return s;
  s.share = s.low = s.high = period == 2 ? 1.0 : 0.0;
  return s;
}

namespace {
// A share's Wilson interval at z: none for an exact share, the stored one at 95 %.
void interval(const StateShare& s, double z, double& low, double& high) {
  low = s.low;
  high = s.high;
  if (s.effective_windows > 0 && z != kZ95)
    wilsonInterval(s.share, s.effective_windows, low, high, z);
}
}  // namespace

ShareDifference shareDifference(const StateShare& a, const StateShare& b, double z) {
  ShareDifference d;
  if (!a.known() || !b.known()) return d;
  d.difference = a.share - b.share;
  double a_low, a_high, b_low, b_high;
  interval(a, z, a_low, a_high);
  interval(b, z, b_low, b_high);
  // Newcombe (1998), eq. for method 10: each side of the interval adds the two Wilson
  // half-widths on the sides that move the difference that way, in quadrature.
  d.low = d.difference - std::hypot(a.share - a_low, b_high - b.share);
  d.high = d.difference + std::hypot(a_high - a.share, b.share - b_low);
  return d;
}

}  // namespace granwave
