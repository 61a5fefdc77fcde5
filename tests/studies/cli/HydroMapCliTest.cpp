// `granwave hydro` across the map the solver must hold on (docs/hydro.md, "Where it holds: the
// map"), end to end as a user runs it. Label `validation`: the same solver and command paths
// as the integration tier's hydro tests, at the map's scale (seven runs; under the sanitizers
// they took 50 s of CI), so the sanitizer pass leaves them to the Release build.
#include <gtest/gtest.h>

#include <string>

#include "tests/studies/cli/CliTestSupport.hpp"

using granwave::testing::CliResult;
using granwave::testing::CliTest;

namespace {
class HydroMapCli : public CliTest {};
}  // namespace

// A coarse subset of the map: corners of the stability grid, a deep layer, the wet law's
// extremes, both closure sets, rough particles and a loose tolerance on a fine grid, all wet
// (the first solver failed on each). No case may fail numerically; each ends in a periodic
// state of period 1-4, a physical diagnosis (at rest, moving as a solid), or no period within
// its 40 cycles.
TEST_F(HydroMapCli, CoarseSubsetOfTheParameterMapRunsWithoutNumericalFailure) {
  write("s.toml",
        "[contact]\nrestitution = \"wet\"\n[run]\nphases_per_cycle = 50\nduration = 4.0\n");
  const char* cases[] = {
      "--set drive.gamma=1.5 --set hydro.cells=60",
      "--set drive.frequency=30 --set drive.gamma=8 --set hydro.cells=60 --set run.duration=1.34",
      "--set particles.count=600 --set hydro.cells=100",
      "--set contact.stokes_critical=80 --set contact.e_inf=0.8 --set hydro.cells=60",
      "--set hydro.transport=\"garzo-dufty\" --set hydro.cells=60",
      ("--set hydro.particles=\"rough\" --set drive.frequency=15 --set drive.gamma=6 "
       "--set hydro.cells=60 --set run.duration=2.67"),
      "--set hydro.rtol=1e-3 --set hydro.cells=200",
  };
  for (const char* args : cases) {
    SCOPED_TRACE(args);
    const CliResult r = run(std::string("hydro -q s.toml -o h.h5 ") + args);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::size_t at = r.out.find("centre-of-mass period ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string period = r.out.substr(at + 22, r.out.find('\n', at) - at - 22);
    const bool undecided = r.out.find("NOT reached after 40 cycles") != std::string::npos;
    EXPECT_TRUE(period == "1T" || period == "2T" || period == "3T" || period == "4T" || undecided)
        << r.out;
  }
}
