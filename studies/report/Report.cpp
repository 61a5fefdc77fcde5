#include "studies/report/Report.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace granwave {

namespace {

// The points of `s` beyond one edge (above: y > edge, else y < edge), drawn on that edge.
Series pointsAtEdge(const Series& s, double edge, bool above, int& count, double& extreme) {
  Series out = s;
  out.x.clear();
  out.y.clear();
  out.xerr.clear();
  out.yerr.clear();
  // A moved std::string, not a literal: GCC 12 warns falsely (-Wrestrict, GCC bug 105329).
  out.marker = std::string(above ? "$\\uparrow$" : "$\\downarrow$");
  out.label = s.label.empty() ? "" : s.label + " (off the axis)";
  out.markersize = 12;  // an arrow glyph is drawn smaller than a filled marker
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!(above ? s.y[i] > edge : s.y[i] < edge)) continue;
    extreme = count == 0 ? s.y[i] : above ? std::max(extreme, s.y[i]) : std::min(extreme, s.y[i]);
    ++count;
    out.x.push_back(s.x[i]);
    out.y.push_back(edge);
  }
  return out;
}

}  // namespace

Series lineSeries(std::vector<double> x, std::vector<double> y, std::string label,
                  std::string color) {
  Series s;
  s.x = std::move(x);
  s.y = std::move(y);
  s.label = std::move(label);
  s.color = std::move(color);
  return s;
}

Series errorSeries(std::vector<double> x, std::vector<double> y, std::vector<double> yerr,
                   std::string label, std::string color) {
  Series s = lineSeries(std::move(x), std::move(y), std::move(label), std::move(color));
  s.style = "errorbar";
  s.yerr = std::move(yerr);
  return s;
}

Series horizontalLine(double y, std::string label, double band, std::string color) {
  Series s = lineSeries({0.0}, {y}, std::move(label), std::move(color));
  s.style = "hline";
  if (band > 0) s.yerr = {band};
  s.linestyle = "--";
  return s;
}

OutsideAxis limitYAxis(Figure& fig, double low, double high, const std::string& what,
                       const std::string& unit) {
  OutsideAxis out;
  std::vector<Series> edges;
  std::string where;
  for (Series& s : fig.series) {
    if (s.style != "points") continue;
    int below = 0, above = 0;
    double lowest = low, highest = high;
    Series under = pointsAtEdge(s, low, false, below, lowest);
    Series over = pointsAtEdge(s, high, true, above, highest);
    if (below + above == 0) continue;
    std::vector<double> x, y;  // the points inside stay where they are
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (!(s.y[i] < low || s.y[i] > high)) {
        x.push_back(s.x[i]);
        y.push_back(s.y[i]);
      }
    s.x = std::move(x);
    s.y = std::move(y);
    const std::string name = s.label.empty() ? "unlabelled" : s.label;
    if (above) where += fmt::format("; {} {} above, up to {:.3g} {}", name, above, highest, unit);
    if (below) where += fmt::format("; {} {} below, down to {:.3g} {}", name, below, lowest, unit);
    if (above) edges.push_back(std::move(over));
    if (below) edges.push_back(std::move(under));
    out.below += below;
    out.above += above;
    out.lowest = out.below == below ? lowest : std::min(out.lowest, lowest);
    out.highest = out.above == above ? highest : std::max(out.highest, highest);
  }
  for (Series& e : edges) fig.series.push_back(std::move(e));
  const double margin = 0.03 * (high - low);
  fig.ylim = {low - margin, high + margin};
  if (out.below + out.above == 0) return out;
  const int n = out.below + out.above;
  out.text = fmt::format(
      "The height axis shows {}, {:.3g} to {:.3g} {}; {} point{} outside it, drawn at its edge as "
      "arrows (↑ above, ↓ below): {}.",
      what, low, high, unit, n, n == 1 ? " lies" : "s lie", where.substr(2));
  fig.caption += (fig.caption.empty() ? "" : " ") + out.text;
  return out;
}

}  // namespace granwave
