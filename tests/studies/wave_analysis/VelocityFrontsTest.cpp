// The matching of velocity-jump episodes to the T~g-peak impact fronts that rank them weak and
// strong (studies/wave_analysis/VelocityFronts.cpp, nearestEpisode), and the fronts' transits
// through the layer's mass on a front whose transits are known exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

namespace {

// A uniform layer (area fraction 0.6 on rows 2..50 of 2 mm, empty around) whose falling top
// (-1 m/s) is stopped by a front rising from 7 mm at 2 m/s for 90 phases of 0.5 ms (linear ramp
// over +-2 rows). The share of the mass below a height inside the layer is linear in the
// height, and the front's height linear in time, so both transits are 2 m/s to round-off.
PhaseProfiles risingFront() {
  constexpr double dz = 0.002, dt = 5e-4;
  PhaseProfiles p;
  p.pooled.phases = 120;
  p.pooled.nz = 60;
  for (int j = 0; j < p.pooled.nz; ++j) p.z.push_back((j + 0.5) * dz);
  for (int ph = 0; ph < p.pooled.phases; ++ph) {
    const double zf = 0.007 + 2.0 * ph * dt;
    for (int j = 0; j < p.pooled.nz; ++j) {
      const bool layer = j >= 2 && j <= 50;
      const double w = std::clamp((p.z[j] - zf + 2 * dz) / (4 * dz), 0.0, 1.0);
      const double v = ph < 90 ? (1 - w) * 0.5 + w * -1.0 : 0.5;
      p.pooled.profile_area_fraction.push_back(layer ? 0.6 : 0.0);
      p.pooled.profile_velocity_z.push_back(layer ? v : NAN);
    }
  }
  return p;
}

}  // namespace

TEST(VelocityFronts, FrontRisingAtConstantSpeedThroughAUniformLayerHasThatSpeedAsBothTransits) {
  const VelocityFronts v = velocityFronts(risingFront(), 5e-4);
  ASSERT_TRUE(v.speed.valid()) << v.why_none;
  EXPECT_NEAR(v.speed.value, 2.0, 1e-9);
  for (const TransitSpeeds& t : v.transit) {
    EXPECT_EQ(t.fronts, 1);
    EXPECT_EQ(t.resolved, 1);
    EXPECT_NEAR(t.speed.value, 2.0, 1e-9);
    EXPECT_FALSE(std::isfinite(t.lower_bound));
  }
  // Over two such runs: the same speed; a bound of another run is kept as the smallest.
  VelocityFronts bounded;
  bounded.transit[0].lower_bound = 40.0;
  bounded.transit[0].fronts = bounded.transit[0].reached = 1;
  const VelocityFronts both = combineVelocityFronts({v, v, bounded});
  EXPECT_NEAR(both.transit[0].speed.value, 2.0, 1e-9);
  EXPECT_EQ(both.transit[0].resolved, 2);
  EXPECT_EQ(both.transit[0].lower_bound, 40.0);
  EXPECT_EQ(transitCell(bounded.transit[0]), "> 40.0 (within fewer phases than a speed needs)");
}
