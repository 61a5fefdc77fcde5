#include "studies/statistics/StateShare.hpp"

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

ShareDifference shareDifference(const StateShare& a, const StateShare& b) {
  ShareDifference d;
  if (!a.known() || !b.known()) return d;
  d.difference = a.share - b.share;
  // Newcombe (1998), eq. for method 10: each side of the interval adds the two Wilson
  // half-widths on the sides that move the difference that way, in quadrature.
  d.low = d.difference - std::hypot(a.share - a.low, b.high - b.share);
  d.high = d.difference + std::hypot(a.high - a.share, b.share - b.low);
  return d;
}

}  // namespace granwave
