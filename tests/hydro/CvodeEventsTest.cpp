// CvodeIntegrator's events (CVODE's root finding, a jump of the state, a restart): a ball
// dropped on a floor with restitution e, whose bounces are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hydro/CvodeIntegrator.hpp"

namespace granwave::hydro {
namespace {

constexpr double kG = 9.81, kDrop = 1.0;

// y = (height, velocity); one event, the height; at it the velocity reverses times e.
// steps_before: the integrator's step count as each bounce is handled, before its restart
// (null: not recorded).
CvodeIntegrator bouncingBall(double e, std::vector<double>& bounce_times, long max_events,
                             const CvodeIntegrator* const* counted = nullptr,
                             std::vector<long>* steps_before = nullptr) {
  CvodeOptions o;
  o.rtol = 1e-10;
  o.atol = {1e-12, 1e-12};
  o.band_upper = o.band_lower = 1;
  o.events = 1;
  o.max_events = max_events;
  o.event_functions = [](double, const double* y, double* g) { g[0] = y[0]; };
  o.on_event = [e, &bounce_times, counted, steps_before](double t, std::vector<double>& y,
                                                         const std::vector<int>& f) {
    if (steps_before) steps_before->push_back((*counted)->stats().steps);
    EXPECT_EQ(f.size(), 1u);
    EXPECT_NE(f[0], 0);
    bounce_times.push_back(t);
    y[0] = 0;
    y[1] = -e * y[1];
  };
  return CvodeIntegrator(
      [](double, const double* y, double* d) {
        d[0] = y[1];
        d[1] = -kG;
        return 0;
      },
      0.0, {kDrop, 0.0}, o);
}

TEST(CvodeEvents, BallBouncesWhereFreeFallSaysAndTheCountersSurviveTheRestarts) {
  // Free fall from height h: the first impact at t1 = sqrt(2 h / g) with speed v1 = g t1; each
  // bounce leaves with e v and returns 2 e v / g later. Root finding locates the impacts to
  // CVODE's root tolerance (~1e-14 s here); asserted to 1e-7 s, the integration's own error.
  const double e = 0.5;
  std::vector<double> bounces;
  std::vector<long> steps_before;
  const CvodeIntegrator* counted = nullptr;
  CvodeIntegrator cv = bouncingBall(e, bounces, 100, &counted, &steps_before);
  counted = &cv;
  cv.advanceTo(1.2);
  const double t1 = std::sqrt(2 * kDrop / kG);
  ASSERT_EQ(bounces.size(), 3u);  // t1 = 0.452, then +0.452, +0.226 s; the next at 1.24 s
  double expected = t1, speed = kG * t1;
  for (std::size_t k = 0; k < bounces.size(); ++k) {
    EXPECT_NEAR(bounces[k], expected, 1e-7) << "bounce " << k;
    speed *= e;
    expected += 2 * speed / kG;
  }
  // At t = 1.2 s the ball is in the flight after the third bounce.
  const double since = 1.2 - bounces.back(), v0 = kG * t1 * e * e * e;
  EXPECT_NEAR(cv.state()[0], v0 * since - 0.5 * kG * since * since, 1e-7);
  // The step counters run on across the restarts (CVodeReInit zeroes CVODE's own): the count
  // grows from bounce to bounce and past the last, although each flight is shorter than the
  // one before (0.45, 0.45, 0.23 s): counts restarted at zero would shrink.
  ASSERT_EQ(steps_before.size(), 3u);
  EXPECT_GT(steps_before[1], steps_before[0]);
  EXPECT_GT(steps_before[2], steps_before[1]);
  EXPECT_GT(cv.stats().steps, steps_before[2]);
  EXPECT_EQ(cv.stats().events, 3);
}

TEST(CvodeEvents, MoreEventsThanTheBudgetEndTheIntegrationWithAnError) {
  // e = 0.9: bounces at 0.45 s and then every 0.81, 0.73, 0.66, 0.59 s, so the sixth comes at
  // 3.7 s; with a budget of 5 events, integrating to 5 s must stop with an error, not go on.
  std::vector<double> bounces;
  CvodeIntegrator cv = bouncingBall(0.9, bounces, 5);
  try {
    cv.advanceTo(5.0);
    FAIL() << "no error after " << bounces.size() << " bounces";
  } catch (const CvodeError& err) {
    EXPECT_NE(std::string(err.what()).find("more than 5 events"), std::string::npos) << err.what();
  }
  EXPECT_EQ(bounces.size(), 5u);
}

TEST(CvodeEvents, EventsWithoutTheirHandlerAreRefused) {
  CvodeOptions o;
  o.atol = {1e-12};
  o.events = 1;
  o.event_functions = [](double, const double* y, double* g) { g[0] = y[0]; };
  const RightHandSide growth = [](double, const double*, double* d) {
    d[0] = 1;
    return 0;
  };
  EXPECT_THROW(CvodeIntegrator(growth, 0.0, {0.0}, o), std::invalid_argument);
}

}  // namespace
}  // namespace granwave::hydro
