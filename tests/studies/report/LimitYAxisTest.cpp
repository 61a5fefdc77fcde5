// A figure's height axis limited to a range (the box): the points outside it are drawn at its
// edge, counted and named in the caption, never dropped.
#include <gtest/gtest.h>

#include "studies/report/Report.hpp"

using granwave::Figure;
using granwave::Series;

namespace {

Series points(std::vector<double> y, std::string label) {
  std::vector<double> x;
  for (std::size_t i = 0; i < y.size(); ++i) x.push_back(static_cast<double>(i));
  Series s = granwave::lineSeries(x, std::move(y), std::move(label), "tab:blue");
  s.style = "points";
  return s;
}

}  // namespace

TEST(LimitYAxis, PointsOutsideTheRangeMoveToItsEdgeAndTheCaptionCountsThem) {
  Figure fig;
  fig.caption = "Fronts.";
  fig.series = {points({5, 262.3, 12, -0.6, 40}, "hydro wet"), points({1, 2}, "ED wet"),
                granwave::lineSeries({0, 1}, {100, 200}, "a line")};
  const granwave::OutsideAxis out = granwave::limitYAxis(fig, 0, 30, "the box", "d");
  EXPECT_EQ(out.above, 2);
  EXPECT_EQ(out.below, 1);
  EXPECT_DOUBLE_EQ(out.highest, 262.3);
  EXPECT_DOUBLE_EQ(out.lowest, -0.6);
  ASSERT_EQ(fig.ylim.size(), 2u);
  EXPECT_DOUBLE_EQ(fig.ylim[0], -0.9);  // 3 % margin
  EXPECT_DOUBLE_EQ(fig.ylim[1], 30.9);
  // The points inside stay; the outside ones become two series at the edges.
  EXPECT_EQ(fig.series[0].y, (std::vector<double>{5, 12}));
  EXPECT_EQ(fig.series[1].y, (std::vector<double>{1, 2}));      // all inside: untouched
  EXPECT_EQ(fig.series[2].y, (std::vector<double>{100, 200}));  // lines are not moved
  ASSERT_EQ(fig.series.size(), 5u);
  EXPECT_EQ(fig.series[3].y, (std::vector<double>{30, 30}));
  EXPECT_EQ(fig.series[3].x, (std::vector<double>{1, 4}));
  EXPECT_EQ(fig.series[4].y, (std::vector<double>{0}));
  EXPECT_EQ(fig.series[3].label, "hydro wet (off the axis)");
  EXPECT_EQ(fig.caption,
            "Fronts. The height axis shows the box, 0 to 30 d; 3 points lie outside it, drawn "
            "at its edge as arrows (↑ above, ↓ below): hydro wet 2 above, up to 262 d; hydro "
            "wet 1 below, down to -0.6 d.");
}

TEST(LimitYAxis, NothingOutsideLeavesTheCaptionAndSeriesAlone) {
  Figure fig;
  fig.caption = "Fronts.";
  fig.series = {points({5, 12}, "ED dry")};
  const granwave::OutsideAxis out = granwave::limitYAxis(fig, 0, 30, "the box", "d");
  EXPECT_EQ(out.above + out.below, 0);
  EXPECT_TRUE(out.text.empty());
  EXPECT_EQ(fig.caption, "Fronts.");
  EXPECT_EQ(fig.series.size(), 1u);
  EXPECT_EQ(fig.ylim.size(), 2u);
}
