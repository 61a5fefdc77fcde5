#pragma once
// How studies store their numbers under /results of results.h5 (docs/studies.md): a value
// with its error as attributes `<name>` and `<name>_error` of a group, series as datasets
// with a "unit" attribute.
#include <string>
#include <vector>

#include "h5/File.hpp"
#include "studies/statistics/Measurement.hpp"

namespace granwave {

void putMeasurement(h5::File& f, const std::string& group, const std::string& name,
                    const Measurement& m);
void putValue(h5::File& f, const std::string& group, const std::string& name, double value);
void putSeries(h5::File& f, const std::string& path, const std::vector<double>& values,
               const std::string& unit);

}  // namespace granwave
