#include "studies/report/ReportWriter.hpp"

#include <fmt/format.h>

namespace granwave {

namespace {

void putVector(h5::File& f, const std::string& path, const std::vector<double>& v) {
  if (!v.empty()) f.writeDataset(path, v, {v.size()});
}

void writeFigure(h5::File& f, const std::string& g, const Figure& fig) {
  f.writeStringAttribute(g, "type", "figure");
  f.writeStringAttribute(g, "title", fig.title);
  f.writeStringAttribute(g, "caption", fig.caption);
  f.writeStringAttribute(g, "xlabel", fig.xlabel);
  f.writeStringAttribute(g, "ylabel", fig.ylabel);
  f.writeStringAttribute(g, "xscale", fig.xscale);
  f.writeStringAttribute(g, "yscale", fig.yscale);
  f.writeAttribute<std::int64_t>(g, "legend", fig.legend ? 1 : 0);
  if (fig.legend_outside) f.writeAttribute<std::int64_t>(g, "legend_outside", 1);
  if (fig.xlim.size() == 2) f.writeArrayAttribute<double>(g, "xlim", fig.xlim);
  if (fig.ylim.size() == 2) f.writeArrayAttribute<double>(g, "ylim", fig.ylim);
  f.createGroup(g + "/series");
  for (std::size_t k = 0; k < fig.series.size(); ++k) {
    const Series& s = fig.series[k];
    const std::string sg = fmt::format("{}/series/{:02d}", g, k);
    f.createGroup(sg);
    f.writeStringAttribute(sg, "style", s.style);
    f.writeStringAttribute(sg, "label", s.label);
    if (!s.color.empty()) f.writeStringAttribute(sg, "color", s.color);
    if (!s.linestyle.empty()) f.writeStringAttribute(sg, "linestyle", s.linestyle);
    if (!s.marker.empty()) f.writeStringAttribute(sg, "marker", s.marker);
    if (s.linewidth > 0) f.writeAttribute<double>(sg, "linewidth", s.linewidth);
    if (s.markersize > 0) f.writeAttribute<double>(sg, "markersize", s.markersize);
    putVector(f, sg + "/x", s.x);
    putVector(f, sg + "/y", s.y);
    putVector(f, sg + "/xerr", s.xerr);
    putVector(f, sg + "/yerr", s.yerr);
    putVector(f, sg + "/y_low", s.y_low);
    putVector(f, sg + "/y_high", s.y_high);
  }
  if (!fig.image.empty()) {
    const Image& im = fig.image.front();
    const std::string ig = g + "/image";
    f.createGroup(ig);
    f.writeDataset(ig + "/values", im.values,
                   {static_cast<std::size_t>(im.ny), static_cast<std::size_t>(im.nx)});
    f.writeAttribute<double>(ig, "x0", im.x0);
    f.writeAttribute<double>(ig, "x1", im.x1);
    f.writeAttribute<double>(ig, "y0", im.y0);
    f.writeAttribute<double>(ig, "y1", im.y1);
    f.writeStringAttribute(ig, "label", im.label);
    f.writeStringAttribute(ig, "cmap", im.cmap);
    if (!im.x_labels.empty()) f.writeStringArrayAttribute(ig, "x_labels", im.x_labels);
    if (!im.y_labels.empty()) f.writeStringArrayAttribute(ig, "y_labels", im.y_labels);
    if (!im.category_labels.empty()) {
      f.writeStringArrayAttribute(ig, "category_labels", im.category_labels);
      f.writeStringArrayAttribute(ig, "category_colors", im.category_colors);
    }
  }
}

void writeTable(h5::File& f, const std::string& g, const Table& t) {
  f.writeStringAttribute(g, "type", "table");
  f.writeStringAttribute(g, "title", t.title);
  f.writeStringAttribute(g, "caption", t.caption);
  f.writeStringArrayAttribute(g, "columns", t.columns);
  std::vector<std::string> cells;
  if (t.rows.empty()) {  // every run failed, or nothing was found: say so in the table
    cells.emplace_back("none: the runs failed or gave nothing to tabulate");
    for (std::size_t c = 1; c < t.columns.size(); ++c) cells.push_back("–");
  }
  for (const auto& row : t.rows) {
    for (std::size_t c = 0; c < t.columns.size(); ++c)
      cells.push_back(c < row.size() ? row[c] : std::string());
  }
  f.writeStringArrayAttribute(g, "cells", cells);
}

}  // namespace

void writeReport(h5::File& f, const Report& report) {
  f.createGroup("/report/sections");
  f.writeStringAttribute("/report", "title", report.title);
  f.writeStringAttribute("/report", "summary", report.summary);
  for (std::size_t s = 0; s < report.sections.size(); ++s) {
    const ReportSection& sec = report.sections[s];
    const std::string sg = fmt::format("/report/sections/{:02d}", s);
    f.createGroup(sg + "/items");
    f.writeStringAttribute(sg, "title", sec.title);
    f.writeStringAttribute(sg, "text", sec.text);
    for (std::size_t i = 0; i < sec.items.size(); ++i) {
      const ReportItem& it = sec.items[i];
      const std::string ig = fmt::format("{}/items/{:02d}", sg, i);
      f.createGroup(ig);
      switch (it.type) {
        case ReportItem::Type::Text:
          f.writeStringAttribute(ig, "type", "text");
          f.writeStringAttribute(ig, "text", it.text);
          break;
        case ReportItem::Type::Figure:
          writeFigure(f, ig, it.figure);
          break;
        case ReportItem::Type::Table:
          writeTable(f, ig, it.table);
          break;
      }
    }
  }
}

}  // namespace granwave
