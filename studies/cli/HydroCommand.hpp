#pragma once
// `granwave hydro SCENE.toml [-o HYDRO.h5] [--set section.key=value]... [-q]`: integrates the
// 1D granular hydrodynamics of the scene to its periodic state, writes the fields at M
// phases per cycle (plate frame and mapped onto the coarse-graining's lab grid) and runs the
// same front detection as `granwave fields` on them.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace granwave {

struct HydroOptions {
  std::string scene_path;
  std::string output;  // default <scene>.hydro.h5
  std::vector<std::string> overrides;
  bool quiet = false;
};

void addHydroCommand(CLI::App& app, HydroOptions& options);
int runHydro(const HydroOptions& options);

}  // namespace granwave
