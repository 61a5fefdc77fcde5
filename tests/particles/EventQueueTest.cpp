// The indexed heap against a trivially correct reference (linear scan), as DynamO tests
// its event sorters.
#include <gtest/gtest.h>

#include <random>

#include "particles/EventQueue.hpp"

TEST(EventQueue, TopAlwaysMatchesLinearScanUnderRandomUpdates) {
  const int n = 257;
  granwave::EventQueue q(n);
  std::vector<double> ref(n, std::numeric_limits<double>::infinity());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int step = 0; step < 20000; ++step) {
    const int id = pick(rng);
    const double t = step % 5 == 0 ? std::numeric_limits<double>::infinity() : u(rng);
    q.update(id, t);
    ref[id] = t;
    const auto it = std::min_element(ref.begin(), ref.end());
    ASSERT_EQ(q.topTime(), *it);
    ASSERT_EQ(ref[q.top()], *it);
  }
}
