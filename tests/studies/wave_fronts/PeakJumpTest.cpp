// The T~g peak that jumps instead of travelling (studies/wave_fronts/WaveFrontsAnalysis.cpp,
// peakJumps): the test the wave-fronts report counts on the paper's scene.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/wave_fronts/WaveFrontsAnalysis.hpp"

using namespace granwave;

TEST(PeakJump, APeakThatRisesTwentyMillimetresInOnePhaseJumpsOneThatClimbsDoesNot) {
  // Front heights (m) over 8 phases of a 10-phase window: a climb at 1 mm per phase, then a
  // rise of 15 mm between phases 5 and 6 (the top of the layer). Limit 5 mm per phase.
  PhaseProfiles p;
  p.pooled.phases = 10;
  p.front_height = {0.000, 0.001, 0.002, 0.003, 0.004, 0.005, 0.020, 0.021, NAN, NAN};
  FrontEpisode climbing, jumping, wrapped;
  climbing.first_phase = 0;
  climbing.last_phase = 5;
  jumping.first_phase = 0;
  jumping.last_phase = 7;
  EXPECT_FALSE(peakJumps(p, climbing, 0.005));
  EXPECT_TRUE(peakJumps(p, jumping, 0.005));
  // An episode across the window's end: phases 8, 9 (no peak: NaN never counts), 0, 1.
  wrapped.first_phase = 8;
  wrapped.last_phase = 1;
  EXPECT_FALSE(peakJumps(p, wrapped, 0.005));
  p.front_height[9] = -0.010;  // from -10 mm at phase 9 to 0 at phase 0: a rise of 10 mm
  EXPECT_TRUE(peakJumps(p, wrapped, 0.005));
}
