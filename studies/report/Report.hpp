#pragma once
// The report of a study as plain values: sections of text, figures (series and an optional
// image) and tables. It is written into results.h5 under /report (ReportWriter) and drawn by
// studies/report/render_report.py, so the page shows nothing that is not in the file.
#include <deque>
#include <string>
#include <vector>

namespace granwave {

struct Series {
  // "line", "points", "errorbar", "step", "hline", "vline", "band", "bar"
  std::string style = "line";
  std::string label;  // empty: no legend entry
  std::vector<double> x, y, xerr, yerr;
  std::vector<double> y_low, y_high;  // band
  std::string color, linestyle, marker;
  double linewidth = 0;   // 0: matplotlib's default
  double markersize = 0;  // points; 0: matplotlib's default
};

struct Image {
  std::vector<double> values;  // [ny][nx], row-major, NaN = blank
  int nx = 0, ny = 0;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  std::string label, cmap = "viridis";
  // Optional names of the columns and rows, drawn as tick labels at their centres.
  std::vector<std::string> x_labels, y_labels;
  // Optional categories: value k (0, 1, ...) means category_labels[k], drawn in
  // category_colors[k] with a key instead of a continuous colour scale.
  std::vector<std::string> category_labels, category_colors;
};

struct Figure {
  std::string title, caption, xlabel, ylabel;
  std::string xscale = "linear", yscale = "linear";
  std::vector<Series> series;
  std::vector<Image> image;  // zero or one
  bool legend = true;
  bool legend_outside = false;     // beside the axes, for plots whose points fill them (diagrams)
  std::vector<double> xlim, ylim;  // {low, high} of an axis; empty: fitted to the data
};

// The points of a figure that lie outside the range its height axis shows (limitYAxis).
struct OutsideAxis {
  int below = 0, above = 0;
  double lowest = 0, highest = 0;  // the extreme values among them
  std::string text;                // the caption's sentence about them ("" when none)
};

// Shows y in [low, high] only (plus a margin of 3 %) and moves every point of a "points"
// series that lies outside onto the nearest edge, as a series of its own in the same colour
// marked by an arrow up or down: a few far points cannot squeeze the rest into a corner, and none
// is dropped unseen. The sentence it returns (also appended to the caption) says how many lie
// outside, of which series and how far; `what` names the range ("the box"), `unit` its unit.
OutsideAxis limitYAxis(Figure& fig, double low, double high, const std::string& what,
                       const std::string& unit);

struct Table {
  std::string title, caption;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};

struct ReportItem {
  enum class Type { Text, Figure, Table } type = Type::Text;
  std::string text;
  Figure figure;
  Table table;
};

struct ReportSection {
  std::string title, text;
  std::vector<ReportItem> items;
  void add(Figure f) { items.push_back({ReportItem::Type::Figure, {}, std::move(f), {}}); }
  void add(Table t) { items.push_back({ReportItem::Type::Table, {}, {}, std::move(t)}); }
  void addText(std::string t) { items.push_back({ReportItem::Type::Text, std::move(t), {}, {}}); }
};

struct Report {
  std::string title, summary;
  // A deque, so that a section's reference stays valid while later sections are added.
  std::deque<ReportSection> sections;
  ReportSection& section(std::string title, std::string text = "") {
    sections.push_back({std::move(title), std::move(text), {}});
    return sections.back();
  }
};

// Convenience constructors for the common series.
Series lineSeries(std::vector<double> x, std::vector<double> y, std::string label = "",
                  std::string color = "");
Series errorSeries(std::vector<double> x, std::vector<double> y, std::vector<double> yerr,
                   std::string label = "", std::string color = "");
Series horizontalLine(double y, std::string label = "", double band = 0, std::string color = "");

}  // namespace granwave
