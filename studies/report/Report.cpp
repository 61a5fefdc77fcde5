#include "studies/report/Report.hpp"

namespace granwave {

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

}  // namespace granwave
