// The bootstrap over seeds (studies/statistics/SeedResampling.hpp): draws with replacement from
// a fixed sequence, and the percentile interval of a statistic over the resamples.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/statistics/SeedResampling.hpp"

namespace granwave {
namespace {

TEST(SeedResampling, DrawsAreSeedIndicesWithReplacementAndRepeatExactly) {
  const auto a = seedDraws(5, 200, 17), b = seedDraws(5, 200, 17);
  EXPECT_EQ(a, b);
  ASSERT_EQ(a.size(), 200u);
  bool repeated = false;
  for (const auto& d : a) {
    ASSERT_EQ(d.size(), 5u);
    for (std::size_t k : d) EXPECT_LT(k, 5u);
    for (std::size_t i = 1; i < d.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) repeated |= d[i] == d[j];
  }
  EXPECT_TRUE(repeated);  // P(no repeat in 200 draws of 5 from 5) = (5!/5^5)^200 ~ 0
  EXPECT_TRUE(seedDraws(0, 10, 17).empty());
}

TEST(SeedResampling, PercentilesInterpolateBetweenOrderStatistics) {
  std::vector<double> v;
  for (int i = 100; i >= 0; --i) v.push_back(i);  // 0..100, unsorted
  const PercentileInterval p = percentileInterval(v);
  EXPECT_DOUBLE_EQ(p.median, 50);
  EXPECT_DOUBLE_EQ(p.low, 2.5);
  EXPECT_DOUBLE_EQ(p.high, 97.5);
  EXPECT_EQ(p.resamples, 101);
  const PercentileInterval same = percentileInterval(std::vector<double>(30, 4.0));
  EXPECT_EQ(same.low, 4.0);
  EXPECT_EQ(same.high, 4.0);
  EXPECT_TRUE(std::isnan(percentileInterval({NAN}).median));
}

TEST(SeedResampling, SeedsAreAddedAfterTheLargestUpToTheCap) {
  EXPECT_EQ(seedsAfter({1, 2, 3}, 5), (std::vector<int>{4, 5}));
  EXPECT_EQ(seedsAfter({11, 3}, 4), (std::vector<int>{12, 13}));
  EXPECT_TRUE(seedsAfter({1, 2, 3}, 3).empty());
  EXPECT_EQ(seedsAfter({}, 2), (std::vector<int>{1, 2}));
}

}  // namespace
}  // namespace granwave
