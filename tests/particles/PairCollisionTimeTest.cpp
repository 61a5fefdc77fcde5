// Pair collision time: smallest tau >= 0 with |r + v tau| = d (a quadratic).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "particles/PairCollisionTime.hpp"

using granwave::pairCollisionTime;

TEST(PairCollisionTime, HeadOnApproachMeetsAfterGapOverSpeed) {
  // Centres 3 apart, diameter 1, closing at 2: touch after (3 - 1) / 2 = 1.
  EXPECT_NEAR(pairCollisionTime(3, 0, -2, 0, 1), 1.0, 1e-15);
}

TEST(PairCollisionTime, ObliqueApproachMatchesGeometry) {
  // r = (0, 2), v = (1, -2)/|..| * s: analytic root of |r + v t|^2 = d^2.
  const double rx = 0.5, rz = 2.0, vx = -0.1, vz = -1.0, d = 1.0;
  const double t = pairCollisionTime(rx, rz, vx, vz, d);
  EXPECT_NEAR(std::hypot(rx + vx * t, rz + vz * t), d, 1e-14);
  const double a = vx * vx + vz * vz, b = rx * vx + rz * vz, c = rx * rx + rz * rz - d * d;
  EXPECT_NEAR(t, (-b - std::sqrt(b * b - a * c)) / a, 1e-14);
}

TEST(PairCollisionTime, RecedingOrMissingPairsNeverCollide) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(pairCollisionTime(3, 0, 2, 0, 1), inf);      // receding
  EXPECT_EQ(pairCollisionTime(3, 0, -1, 5, 1), inf);     // passes by (b < 0, disc < 0)
  EXPECT_EQ(pairCollisionTime(0.999, 0, 1, 0, 1), inf);  // overlapping but receding
}

TEST(PairCollisionTime, OverlappingApproachingPairCollidesAtOnce) {
  EXPECT_EQ(pairCollisionTime(0.999, 0, -1, 0, 1), 0.0);
}

TEST(PairCollisionTime, TouchingPairWithRoundOffApproachDoesNotCollide) {
  // After an e_n = 0 collision the normal relative velocity is zero up to round-off; a
  // tangentially moving touching pair must not be collided again "at once" forever.
  const double inf = std::numeric_limits<double>::infinity();
  // Approach speed 1e-17 against a round-off tolerance of 1e-9 x (speeds ~ 0.3).
  EXPECT_EQ(pairCollisionTime(1.0, 0, -1e-17, 0.3, 1.0, 3e-10), inf);
  EXPECT_EQ(pairCollisionTime(1.0, 0, -1e-3, 0.3, 1.0, 3e-10), 0.0);
}

TEST(PairCollisionTime, PairAtRoundOffGapClosingByRoundOffDoesNotCollide) {
  // A gap of round-off (|r|^2 - d^2 <= 2e-10 d^2) is contact for the tolerance test: closing
  // by less than round-off, never; faster, at the straight line's time, as without it.
  const double inf = std::numeric_limits<double>::infinity();
  // Head-on; the tolerance 3e-10 stands for 1e-9 x speeds ~ 0.3.
  EXPECT_EQ(pairCollisionTime(1.0 + 1e-14, 0, -1e-12, 0, 1.0, 3e-10), inf);
  EXPECT_NEAR(pairCollisionTime(1.0 + 1e-14, 0, -1e-3, 0, 1.0, 3e-10), 1e-11, 1e-13);
  // Without a tolerance (the engine's first pass) the slow pair still has its time.
  EXPECT_NEAR(pairCollisionTime(1.0 + 1e-14, 0, -1e-12, 0, 1.0), 1e-2, 1e-4);
  // A real gap (1e-6) closing slowly is not contact: it collides when it gets there.
  EXPECT_NEAR(pairCollisionTime(1.0 + 1e-6, 0, -1e-12, 0, 1.0, 3e-10), 1e6, 1.0);
}

TEST(PairCollisionTime, StableForTinyGapsAndLargeSpeeds) {
  // Cancellation-free root: gap 1e-12 at speed 1e3 -> 1e-15. The gap itself is only known
  // to eps / 1e-12 ~ 1e-4 relative (1 + 1e-12 is rounded), which bounds the accuracy.
  const double t = pairCollisionTime(1.0 + 1e-12, 0, -1e3, 0, 1.0);
  EXPECT_NEAR(t, 1e-15, 2e-4 * 1e-15);
}

TEST(RiderPairCollisionTime, RidersMeetOnlyHorizontally) {
  // Vertical offset 0.6 d: contact at |rx| = 0.8 d; closing at 2 from rx = 1.8 -> t = 0.5.
  EXPECT_NEAR(granwave::riderPairCollisionTime(1.8, 0.6, -2.0, 1.0), 0.5, 1e-15);
  // Vertically a diameter or more apart: never.
  EXPECT_EQ(granwave::riderPairCollisionTime(0.1, 1.0, -2.0, 1.0),
            std::numeric_limits<double>::infinity());
  // Overlapping by round-off (vertical offset just under d) and sliding apart: never;
  // sliding together: at once.
  EXPECT_EQ(granwave::riderPairCollisionTime(1e-5, 0.99999998, 1e-4, 1.0),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(granwave::riderPairCollisionTime(1e-5, 0.99999998, -1e-4, 1.0), 0.0);
}

TEST(RiderPairCollisionTime, RidersStackedExactlyNeverApproach) {
  // One on top of the other (rx = 0, as two riders both against a side wall): the normal is
  // vertical and sliding sideways either way moves them apart. Both signs once counted as
  // "closing at once", and two such riders swapped their vx forever at one instant.
  constexpr double never = std::numeric_limits<double>::infinity();
  EXPECT_EQ(granwave::riderPairCollisionTime(0.0, 0.99999998, 1e-4, 1.0), never);
  EXPECT_EQ(granwave::riderPairCollisionTime(0.0, 0.99999998, -1e-4, 1.0), never);
  EXPECT_EQ(granwave::riderPairCollisionTime(-0.0, 0.99999998, 1e-4, 1.0), never);
  // Touching at a slant, the normal approach speed -rx vx / d decides against the tolerance:
  // 1e-5 * 1e-4 = 1e-9 approaches, with a tolerance of 2e-9 it is round-off.
  EXPECT_EQ(granwave::riderPairCollisionTime(1e-5, 0.99999998, -1e-4, 1.0, 2e-9), never);
  EXPECT_EQ(granwave::riderPairCollisionTime(1e-5, 0.99999998, -1e-4, 1.0, 5e-10), 0.0);
}

TEST(RiderPairCollisionTime, GrazingContactOfAlmostStackedRidersIsNoCollision) {
  // rz = sqrt(1 - 1e-12) d: contact at |rx| = 1e-6 d. From rx = 2e-6 closing at 1e-4 the pair
  // touches after 1e-2 with a normal approach speed of 1e-4 * 1e-6 = 1e-10: a collision above
  // a tolerance of 1e-11, none (the pair slides past) below one of 1e-9. Without the test the
  // engine predicted that grazing contact at once, again and again (a Zeno cascade).
  const double rz = std::sqrt(1.0 - 1e-12);
  EXPECT_NEAR(granwave::riderPairCollisionTime(2e-6, rz, -1e-4, 1.0, 1e-11), 1e-2, 1e-6);
  EXPECT_EQ(granwave::riderPairCollisionTime(2e-6, rz, -1e-4, 1.0, 1e-9),
            std::numeric_limits<double>::infinity());
}
