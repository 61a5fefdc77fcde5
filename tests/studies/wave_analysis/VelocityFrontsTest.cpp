// The matching of velocity-jump episodes to the T~g-peak impact fronts that rank them weak and
// strong (studies/wave_analysis/VelocityFronts.cpp, nearestEpisode).
#include <gtest/gtest.h>

#include <vector>

#include "studies/wave_analysis/VelocityFronts.hpp"

using namespace granwave;

TEST(VelocityFronts, AnEpisodeIsMatchedAcrossTheWindowsEndAndOnlyWithinThreePhases) {
  // Window of 200 phases: episodes starting at 95 and 196. A T~g front at phase 1 is 5 phases
  // from 196 across the end: too far; at 198 it is 2 phases away; at 93, 2 from 95.
  const std::vector<int> starts = {95, 196};
  EXPECT_EQ(nearestEpisode(starts, 93, 200, 3), 0);
  EXPECT_EQ(nearestEpisode(starts, 198, 200, 3), 1);
  EXPECT_EQ(nearestEpisode(starts, 199, 200, 3), 1);  // 3 phases: still within
  EXPECT_EQ(nearestEpisode(starts, 1, 200, 3), -1);   // 5 phases across the end
  EXPECT_EQ(nearestEpisode(starts, 1, 200, 5), 1);
  EXPECT_EQ(nearestEpisode({}, 10, 200, 3), -1);
}
