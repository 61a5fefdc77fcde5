#include "studies/method_comparison/MethodRuns.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "studies/statistics/Measurement.hpp"
#include "studies/statistics/SeedResampling.hpp"

namespace granwave {

namespace {

// The LAMMPS executable: a path, or a name looked up on PATH; empty if not found.
std::string findProgram(const std::string& exe) {
  if (exe.find('/') != std::string::npos) return std::filesystem::exists(exe) ? exe : "";
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (std::filesystem::exists(std::filesystem::path(dir) / exe))
      return (std::filesystem::path(dir) / exe).string();
  return "";
}

}  // namespace

std::string MethodComparisonConfig::failureHydroRun(int law, double gamma, int cells, double rtol) {
  return hydroRun(law, fmt::format("Gamma={} {} cells rtol {}", formatCompact(gamma), cells,
                                   formatCompact(rtol)));
}

std::string MethodComparisonConfig::costHydroRun(int cells, double rtol) {
  return hydroRun(1, fmt::format("{} cells rtol {}", cells, formatCompact(rtol)));
}

std::string MethodComparisonConfig::lammpsRun() const {
  return fmt::format("LAMMPS dry seed {}", lammps_seed);
}

std::vector<int> MethodComparisonConfig::extraSeeds() const { return seedsAfter(seeds, max_seeds); }

std::vector<int> seedsOf(const MethodComparisonConfig& c, const RunSet& runs, int law) {
  std::vector<int> seeds = c.seeds;
  for (int sd : c.extraSeeds())
    if (runs.has(MethodComparisonConfig::particleRun(law, fmt::format("seed {}", sd))))
      seeds.push_back(sd);
  return seeds;
}

// Where methods fail: ED without TC, hydro over Gamma x grid x tolerance. A failure of these
// runs is a result, and the progress lines say so.
std::vector<PlannedRun> failureMapRuns(const MethodComparisonConfig& c, int law) {
  using C = MethodComparisonConfig;
  const std::string seed1 = fmt::format("run.seed={}", c.seeds.front());
  const std::string expected = "expected failure (failure map)";
  std::vector<PlannedRun> runs;
  for (double gamma : c.fail_gammas) {
    const std::string drive = fmt::format("drive.gamma={}", formatCompact(gamma));
    runs.push_back({RunKind::Particles,
                    law,
                    C::particleRun(law, fmt::format("no TC Gamma={}", formatCompact(gamma))),
                    {"contact.tc=\"off\"", drive, seed1},
                    c.fail_duration,
                    expected});
    for (int cells : c.fail_cells)
      for (double rtol : c.fail_rtol)
        runs.push_back({RunKind::Hydro,
                        law,
                        C::failureHydroRun(law, gamma, cells, rtol),
                        {drive, fmt::format("hydro.cells={}", cells),
                         fmt::format("hydro.rtol={}", formatCompact(rtol))},
                        0,
                        expected});
  }
  return runs;
}

// Sampled as densely as the paper's hydro runs: a deterministic candidate's front error is its
// fit error alone, which more phases narrow. Rough particles: the rotational temperature as a
// field (docs/hydro.md, "Rough particles"), the continuum's answer to the particles' friction.
std::vector<PlannedRun> modelHydroRuns(const MethodComparisonConfig& c, int law) {
  using C = MethodComparisonConfig;
  const std::string phases = fmt::format("run.phases_per_cycle={}", c.sweep_phases);
  return {{RunKind::Hydro,
           law,
           C::hydroRun(law, "Garzo-Dufty"),
           {"hydro.transport=\"garzo-dufty\"", phases},
           0,
           ""},
          {RunKind::Hydro,
           law,
           C::hydroRun(law, "rough"),
           {"hydro.particles=\"rough\"", phases},
           0,
           ""}};
}

// Cost against accuracy, wet layer: ED over the cycles averaged, hydro over grid x tolerance.
std::vector<PlannedRun> costRuns(const MethodComparisonConfig& c) {
  using C = MethodComparisonConfig;
  const std::string seed1 = fmt::format("run.seed={}", c.seeds.front());
  std::vector<PlannedRun> runs;
  for (double d : c.cost_durations)
    runs.push_back({RunKind::Particles,
                    1,
                    C::particleRun(1, fmt::format("{} s", formatCompact(d))),
                    {seed1},
                    d,
                    ""});
  for (int cells : c.cost_cells)
    for (double rtol : c.cost_rtol)
      runs.push_back({RunKind::Hydro,
                      1,
                      C::costHydroRun(cells, rtol),
                      {fmt::format("hydro.cells={}", cells),
                       fmt::format("hydro.rtol={}", formatCompact(rtol))},
                      0,
                      ""});
  return runs;
}

std::optional<RunRequest> lammpsRequest(StudyFile& f, MethodComparisonConfig& c) {
  if (c.lammps_mode == "no") return std::nullopt;
  std::string program = findProgram(c.lammps_executable);
  if (program.empty() && c.lammps_install) {
    fmt::print(stderr, "granwave study: installing Debian's lammps ([lammps] install = true)\n");
    const int rc = std::system(
        "DEBIAN_FRONTEND=noninteractive $( [ \"$(id -u)\" -eq 0 ] || echo sudo ) apt-get "
        "install -y -qq --no-install-recommends lammps >&2");
    if (rc != 0) f.fail("lammps", "install", "apt-get install lammps failed");
    program = findProgram(c.lammps_executable);
  }
  if (program.empty() && c.lammps_mode == "auto") return std::nullopt;  // not installed
  if (program.empty())
    f.fail("lammps", "executable",
           "not found on PATH: install Debian's lammps (apt-get install lammps) or set "
           "[lammps] install = true");
  std::ifstream deck(c.lammps_deck);
  std::ostringstream text;
  text << deck.rdbuf();
  RunRequest q = runRequest(RunKind::Lammps, c.lammpsRun(), c.scenes.base[0]);
  q.program = program;
  q.deck_path = c.lammps_deck;
  q.deck_text = text.str();
  q.variables = {"duration", formatCompact(c.lammps_duration), "seed",
                 std::to_string(c.lammps_seed)};
  c.lammps = true;
  return q;
}

}  // namespace granwave
