#pragma once
// The last section of every study's report and /runs of results.h5: every run of the study
// with its status, wall and CPU time (as measured when the run was made) and its work.
#include "h5/File.hpp"
#include "studies/contract/Study.hpp"
#include "studies/report/Report.hpp"

namespace granwave {

void writeRunCosts(const RunSet& runs, h5::File& f, Report& report);

}  // namespace granwave
