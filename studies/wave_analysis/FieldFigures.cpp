#include "studies/wave_analysis/FieldFigures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace granwave {

Figure spaceTimeFigure(const PhaseProfiles& p, double d, double height, std::string title,
                       std::string caption) {
  Figure fig;
  fig.title = std::move(title);
  fig.caption = std::move(caption);
  fig.xlabel = "t / T";
  fig.ylabel = "z / d (lab frame)";
  Image im;
  im.nx = p.phases();
  im.ny = p.rows();
  im.values.resize(static_cast<std::size_t>(im.nx) * im.ny);
  for (int j = 0; j < p.rows(); ++j)
    for (int k = 0; k < p.phases(); ++k)
      im.values[static_cast<std::size_t>(j) * im.nx + k] =
          p.at(p.pooled.profile_area_fraction, k, j);
  const double dt = p.phases() > 1 ? p.phase[1] - p.phase[0] : 1.0;
  im.x0 = p.phase.front() - 0.5 * dt;
  im.x1 = p.phase.back() + 0.5 * dt;
  im.y0 = (p.z.front() - 0.5 * d) / d;
  im.y1 = (p.z.back() + 0.5 * d) / d;
  im.label = "area fraction";
  im.cmap = "Greys";
  fig.image.push_back(std::move(im));
  std::vector<double> plate, lid, com, front;
  for (int k = 0; k < p.phases(); ++k) {
    plate.push_back(p.plate_height[k] / d);
    lid.push_back((p.plate_height[k] + height) / d);
    com.push_back(p.pooled.center_of_mass_height[k] / d);
    front.push_back(p.front_height[k] / d);
  }
  Series sp = lineSeries(p.phase, plate, "plate", "tab:blue");
  Series sl = lineSeries(p.phase, lid, "lid", "tab:blue");
  sl.linestyle = "--";
  Series sc = lineSeries(p.phase, com, "centre of mass", "gold");
  sc.linewidth = 2;
  Series sf = lineSeries(p.phase, front, "front (T~g peak)", "tab:red");
  sf.style = "points";
  sf.marker.push_back('^');  // not = "^": a GCC 12 -Wrestrict false positive here
  fig.series = {sp, sl, sc, sf};
  // The box over the cycle and the profiles' rows: a front far above it (a hydro layer's few
  // fast cells) would squeeze the layer into a strip; it is drawn at the edge instead.
  if (plate.empty()) return fig;
  const double low = std::min(fig.image.front().y0, *std::min_element(plate.begin(), plate.end()));
  const double high = std::max(fig.image.front().y1, *std::max_element(lid.begin(), lid.end()));
  limitYAxis(fig, low, high, "the rows and the box over the cycle", "d");
  return fig;
}

Figure profilesAtPhases(const PhaseProfiles& p, const std::vector<double>& field, double scale,
                        double d, const std::vector<double>& phases, std::string title,
                        std::string ylabel, std::string caption) {
  Figure fig;
  fig.title = std::move(title);
  fig.caption = std::move(caption);
  fig.xlabel = "z / d (lab frame)";
  fig.ylabel = std::move(ylabel);
  for (double ph : phases) {
    const int k = p.phaseIndex(ph);
    std::vector<double> x, y;
    for (int j = 0; j < p.rows(); ++j) {
      x.push_back(p.z[j] / d);
      y.push_back(p.at(field, k, j) * scale);
    }
    fig.series.push_back(
        lineSeries(x, y, fmt::format("t/T = {:.2f}", p.phase[k] - std::floor(p.phase[k]))));
  }
  return fig;
}

Series centerOfMassSeries(const PhaseProfiles& p, double d, std::string label, std::string color) {
  std::vector<double> y;
  for (int k = 0; k < p.phases(); ++k) y.push_back(p.pooled.center_of_mass_height[k] / d);
  return lineSeries(p.phase, y, std::move(label), std::move(color));
}

}  // namespace granwave
