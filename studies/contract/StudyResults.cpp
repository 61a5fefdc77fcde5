#include "studies/contract/StudyResults.hpp"

namespace granwave {

namespace {

void ensureGroup(h5::File& f, const std::string& group) {
  if (!f.exists(group)) f.createGroup(group);
}

}  // namespace

void putMeasurement(h5::File& f, const std::string& group, const std::string& name,
                    const Measurement& m) {
  ensureGroup(f, group);
  f.writeAttribute<double>(group, name, m.value);
  f.writeAttribute<double>(group, name + "_error", m.error);
}

void putValue(h5::File& f, const std::string& group, const std::string& name, double value) {
  ensureGroup(f, group);
  f.writeAttribute<double>(group, name, value);
}

void putSeries(h5::File& f, const std::string& path, const std::vector<double>& values,
               const std::string& unit) {
  f.writeDataset(path, values, {values.size()});
  f.writeStringAttribute(path, "unit", unit);
}

}  // namespace granwave
