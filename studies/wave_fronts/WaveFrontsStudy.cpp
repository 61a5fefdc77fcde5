#include "studies/wave_fronts/WaveFrontsStudy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/SceneDerived.hpp"
#include "studies/framework/StudyScenes.hpp"

namespace granwave {

namespace {

std::string g(double v) { return fmt::format("{:g}", v); }

}  // namespace

WaveFrontsStudy::WaveFrontsStudy(StudyFile& f) : file_(&f) {
  c_.dry_path = f.scenePath("scenes", "dry", "../scenes/paper-dry.toml");
  c_.wet_path = f.scenePath("scenes", "wet", "../scenes/paper-wet.toml");
  c_.set = f.strings("scenes", "set", {});
  c_.duration = f.number("particles", "duration", c_.duration);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  c_.profile_phases = f.numbers("particles", "profile_phases", c_.profile_phases);
  c_.sweep_duration = f.number("sweep", "duration", c_.sweep_duration);
  c_.counts = f.integers("sweep", "counts", c_.counts);
  c_.stokes = f.numbers("sweep", "stokes_critical", c_.stokes);
  c_.e_inf = f.numbers("sweep", "e_inf", c_.e_inf);
  c_.cost_durations = f.numbers("cost", "durations", c_.cost_durations);
  c_.cost_cells = f.integers("cost", "hydro_cells", c_.cost_cells);
  c_.cost_rtol = f.numbers("cost", "hydro_rtol", c_.cost_rtol);
  c_.fail_gammas = f.numbers("failure", "gammas", c_.fail_gammas);
  c_.fail_duration = f.number("failure", "duration", c_.fail_duration);
  c_.fail_cells = f.integers("failure", "hydro_cells", c_.fail_cells);
  c_.fail_rtol = f.numbers("failure", "hydro_rtol", c_.fail_rtol);
  c_.lammps_mode = f.string("lammps", "run", c_.lammps_mode);
  if (c_.lammps_mode != "auto" && c_.lammps_mode != "yes" && c_.lammps_mode != "no")
    f.fail("lammps", "run", "expected \"auto\", \"yes\" or \"no\"");
  c_.lammps_install = f.boolean("lammps", "install", c_.lammps_install);
  c_.lammps_executable = f.string("lammps", "executable", c_.lammps_executable);
  c_.lammps_duration = f.number("lammps", "duration", c_.lammps_duration);
  c_.lammps_seed = f.integer("lammps", "seed", c_.lammps_seed);
  // The deck: given relative to the study file, else the one shipped in the source tree.
  c_.lammps_deck = f.string("lammps", "deck", "");
  if (c_.lammps_mode != "no")
    c_.lammps_deck = c_.lammps_deck.empty() ? std::string(GRANWAVE_LAMMPS_DECK)
                                            : f.scenePath("lammps", "deck", "");
  if (c_.lammps_mode != "no" && !std::filesystem::exists(c_.lammps_deck))
    f.fail("lammps", "deck", "the LAMMPS deck " + c_.lammps_deck + " does not exist");
  if (c_.window < 1 || c_.window > 4) f.fail("particles", "window_cycles", "expected 1 to 4");
  if (c_.blocks < 2) f.fail("particles", "blocks", "expected at least 2");
  if (!(c_.duration > 0)) f.fail("particles", "duration", "expected a positive time in s");

  base_[0] = studyScene(f, c_.dry_path, c_.set);
  base_[1] = studyScene(f, c_.wet_path, c_.set);
  for (int law = 0; law < 2; ++law) {
    if (!(base_[law].drive.frequency > 0))
      f.fail("scenes", kLawNames[law], "the wave-fronts study needs a driven scene");
    e_eff_[law] = effectiveRestitutionAtT0(base_[law]);
  }

  for (int law = 0; law < 2; ++law) {
    for (int seed : c_.seeds)
      add(RunKind::Particles, law, edLabel(law, fmt::format("seed {}", seed)),
          {fmt::format("run.seed={}", seed)}, c_.duration);
    add(RunKind::Hydro, law, hydroLabel(law, "velocity"), {}, 0);
    add(RunKind::Hydro, law, hydroLabel(law, "constant"),
        {"hydro.restitution_model=\"constant\"", fmt::format("contact.e={:.6f}", e_eff_[law])}, 0);
    for (int n : c_.counts) {
      add(RunKind::Particles, law, edLabel(law, fmt::format("N={}", n)),
          {fmt::format("particles.count={}", n), fmt::format("run.seed={}", c_.seeds.front())},
          c_.sweep_duration);
      add(RunKind::Hydro, law, hydroLabel(law, fmt::format("N={}", n)),
          {fmt::format("particles.count={}", n)}, 0);
    }
    // Where methods fail: ED without TC, hydro over Gamma x grid x tolerance.
    for (double gamma : c_.fail_gammas) {
      add(RunKind::Particles, law, edLabel(law, fmt::format("no TC Gamma={}", g(gamma))),
          {"contact.tc=\"off\"", fmt::format("drive.gamma={}", g(gamma)),
           fmt::format("run.seed={}", c_.seeds.front())},
          c_.fail_duration);
      for (int cells : c_.fail_cells)
        for (double rtol : c_.fail_rtol)
          add(RunKind::Hydro, law,
              hydroLabel(law, fmt::format("Gamma={} {} cells rtol {}", g(gamma), cells, g(rtol))),
              {fmt::format("drive.gamma={}", g(gamma)), fmt::format("hydro.cells={}", cells),
               fmt::format("hydro.rtol={}", g(rtol))},
              0);
    }
    // Simpler models than the full particle model, with the same seeds (the wet layer's
    // period is bistable: one seed would not say which period a model gives).
    for (int sd : c_.seeds) {
      const std::string seed = fmt::format("run.seed={}", sd);
      add(RunKind::Particles, law, edLabel(law, fmt::format("no rotation seed {}", sd)),
          {"contact.friction=0", seed}, c_.duration);
      add(RunKind::Particles, law, edLabel(law, fmt::format("constant e seed {}", sd)),
          {"contact.restitution=\"constant\"", fmt::format("contact.e={:.6f}", e_eff_[law]), seed},
          c_.duration);
    }
    add(RunKind::Hydro, law, hydroLabel(law, "Garzo-Dufty"), {"hydro.transport=\"garzo-dufty\""},
        0);
  }
  if (c_.lammps_mode != "no") addLammps(f);
  for (double st : c_.stokes) {
    add(RunKind::Particles, 1, edLabel(1, fmt::format("St_c={}", g(st))),
        {fmt::format("contact.stokes_critical={}", g(st)),
         fmt::format("run.seed={}", c_.seeds.front())},
        c_.sweep_duration);
    add(RunKind::Hydro, 1, hydroLabel(1, fmt::format("St_c={}", g(st))),
        {fmt::format("contact.stokes_critical={}", g(st))}, 0);
  }
  for (double e : c_.e_inf) {
    add(RunKind::Particles, 1, edLabel(1, fmt::format("e_inf={}", g(e))),
        {fmt::format("contact.e_inf={}", g(e)), fmt::format("run.seed={}", c_.seeds.front())},
        c_.sweep_duration);
    add(RunKind::Hydro, 1, hydroLabel(1, fmt::format("e_inf={}", g(e))),
        {fmt::format("contact.e_inf={}", g(e))}, 0);
  }
  // Cost against accuracy, wet layer: ED over the cycles averaged, hydro over grid x tolerance.
  for (double d : c_.cost_durations)
    add(RunKind::Particles, 1, edLabel(1, fmt::format("{} s", g(d))),
        {fmt::format("run.seed={}", c_.seeds.front())}, d);
  for (int cells : c_.cost_cells)
    for (double rtol : c_.cost_rtol)
      add(RunKind::Hydro, 1, hydroLabel(1, fmt::format("{} cells rtol {}", cells, g(rtol))),
          {fmt::format("hydro.cells={}", cells), fmt::format("hydro.rtol={}", g(rtol))}, 0);
}

// The LAMMPS run of the paper's dry scene (studies/lammps/paper-scene.lmp; its contact model
// has a constant e_n = 0.9, so it stands beside the dry particles). Installs Debian's lammps if
// asked and missing; otherwise a missing executable is a study-file error.
void WaveFrontsStudy::addLammps(StudyFile& f) {
  auto find = [&]() -> std::string {
    const std::string& exe = c_.lammps_executable;
    if (exe.find('/') != std::string::npos) return std::filesystem::exists(exe) ? exe : "";
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "");
    for (std::string dir; std::getline(dirs, dir, ':');)
      if (std::filesystem::exists(std::filesystem::path(dir) / exe))
        return (std::filesystem::path(dir) / exe).string();
    return "";
  };
  std::string program = find();
  if (program.empty() && c_.lammps_install) {
    fmt::print(stderr, "granwave study: installing Debian's lammps ([lammps] install = true)\n");
    const int rc = std::system(
        "DEBIAN_FRONTEND=noninteractive $( [ \"$(id -u)\" -eq 0 ] || echo sudo ) apt-get "
        "install -y -qq --no-install-recommends lammps >&2");
    if (rc != 0) f.fail("lammps", "install", "apt-get install lammps failed");
    program = find();
  }
  if (program.empty() && c_.lammps_mode == "auto") return;  // not installed: left out
  if (program.empty())
    f.fail("lammps", "executable",
           "not found on PATH: install Debian's lammps (apt-get install lammps) or set "
           "[lammps] install = true");
  std::ifstream deck(c_.lammps_deck);
  std::ostringstream text;
  text << deck.rdbuf();
  RunRequest q =
      runRequest(RunKind::Lammps, fmt::format("LAMMPS dry seed {}", c_.lammps_seed), base_[0]);
  q.program = program;
  q.deck_path = c_.lammps_deck;
  q.deck_text = text.str();
  q.variables = {"duration", g(c_.lammps_duration), "seed", std::to_string(c_.lammps_seed)};
  requests_.push_back(std::move(q));
  c_.lammps = true;
}

void WaveFrontsStudy::add(RunKind kind, int law, const std::string& label,
                          std::vector<std::string> overrides, double duration) {
  std::vector<std::string> all = c_.set;
  all.insert(all.end(), overrides.begin(), overrides.end());
  if (kind == RunKind::Particles) all.push_back(fmt::format("run.duration={}", g(duration)));
  RunRequest q;
  q.kind = kind;
  q.label = label;
  q.scene = studyScene(*file_, law == 0 ? c_.dry_path : c_.wet_path, all);
  q.window_cycles = c_.window;
  q.blocks = c_.blocks;
  requests_.push_back(std::move(q));
}

std::unique_ptr<Study> makeWaveFrontsStudy(StudyFile& file) {
  return std::make_unique<WaveFrontsStudy>(file);
}

}  // namespace granwave
