// Period-2 state shares and their comparison (studies/statistics/StateShare.hpp).
#include <gtest/gtest.h>

#include "studies/statistics/StateShare.hpp"

using namespace granwave;

namespace {

StateShare counted(int period2, int windows) { return pooledStateShare(windows, period2, windows); }

}  // namespace

TEST(StateShare, DifferenceIntervalMatchesNewcombesPublishedExamples) {
  // R. G. Newcombe, Statistics in Medicine 17, 873 (1998), Table II, method 10 (hybrid score
  // interval from Wilson score limits), printed to 4 decimals.
  struct Case {
    int a, m, b, n;
    double low, high;
  };
  const Case cases[] = {{56, 70, 48, 80, 0.0524, 0.3339}, {9, 10, 3, 10, 0.1705, 0.8090},
                        {6, 7, 2, 7, 0.0582, 0.8062},     {5, 56, 0, 29, -0.0381, 0.1926},
                        {0, 10, 0, 20, -0.1611, 0.2775},  {10, 10, 0, 20, 0.6791, 1.0000}};
  for (const Case& c : cases) {
    const ShareDifference d = shareDifference(counted(c.a, c.m), counted(c.b, c.n));
    EXPECT_NEAR(d.low, c.low, 6e-5) << c.a << "/" << c.m << " - " << c.b << "/" << c.n;
    EXPECT_NEAR(d.high, c.high, 6e-5) << c.a << "/" << c.m << " - " << c.b << "/" << c.n;
  }
}

TEST(StateShare, EffectiveWindowsNotRawWindowsSetTheWidth) {
  // 60 of 100 windows, but correlated so that only 25 are independent: the interval is that of
  // 15 of 25, not of 60 of 100.
  const StateShare s = pooledStateShare(100, 60, 25);
  const StateShare raw = counted(60, 100);
  EXPECT_DOUBLE_EQ(s.share, 0.6);
  EXPECT_GT(s.high - s.low, 1.8 * (raw.high - raw.low));
  EXPECT_FALSE(pooledStateShare(0, 0, 0).known());
}

TEST(StateShare, DeterministicModelMatchesOnlyASharePlausiblyAtItsOwnValue) {
  // A period-1 model has share 0 exactly: compatible with 0 of 30 windows, not with 5 of 30
  // (Wilson lower limit 0.073 > 0), and a period-2 model not with 0.58 of 60 effective windows.
  EXPECT_TRUE(shareDifference(exactStateShare(1), counted(0, 30)).compatible());
  EXPECT_FALSE(shareDifference(exactStateShare(1), counted(5, 30)).compatible());
  EXPECT_FALSE(shareDifference(exactStateShare(2), pooledStateShare(100, 58, 60)).compatible());
  EXPECT_TRUE(shareDifference(counted(17, 30), pooledStateShare(100, 58, 60)).compatible());
  // A period the windows do not classify (not periodic, 4) compares with nothing.
  EXPECT_FALSE(exactStateShare(0).known());
  EXPECT_FALSE(shareDifference(exactStateShare(4), counted(0, 30)).compatible());
}
