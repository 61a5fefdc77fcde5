#pragma once
// Writes a Report under /report of an open results file (layout: docs/studies.md).
#include "h5/File.hpp"
#include "studies/report/Report.hpp"

namespace granwave {

void writeReport(h5::File& file, const Report& report);

}  // namespace granwave
