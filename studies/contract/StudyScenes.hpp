#pragma once
// The scenes of a study: the dry and the wet layer every study compares ([scenes] dry, wet and
// set of the study file, docs/studies.md), each run's scene as a base scene plus
// `section.key=value` overrides (the same syntax and checks as --set). The hydro closure that
// matches a scene's law is in studies/hydro_run/HydroModel.hpp.
#include <string>
#include <vector>

#include "scene/Scene.hpp"
#include "studies/contract/StudyFile.hpp"

namespace granwave {

// The two laws of the paper, in this order everywhere (index 0 dry, 1 wet), with the colours
// every report draws them in.
inline constexpr int kLaws = 2;
inline constexpr const char* kLawNames[kLaws] = {"dry", "wet"};
inline constexpr const char* kLawColors[kLaws] = {"tab:orange", "tab:blue"};

// Throws StudyError naming the study file, the scene and the override on any scene error.
// Particle runs keep one trajectory frame per cycle (the observables and live fields see
// every record), so a study's run files stay small.
Scene studyScene(const StudyFile& study, const std::string& scene_path,
                 const std::vector<std::string>& overrides);

// [scenes] of a study file: the dry and wet scene files and the overrides for every scene.
struct LawScenes {
  std::string path[kLaws];
  std::vector<std::string> set;
  Scene base[kLaws];  // the scenes with `set` alone, once loadBase has read them

  // Reads [scenes] dry (default ../scenes/paper-dry.toml), wet and set; the files must exist.
  static LawScenes read(StudyFile& file);
  // Reads the two base scenes (StudyError on a bad scene or override).
  void loadBase(const StudyFile& file);
  // The scene of `law` with `set` and then `overrides`.
  Scene scene(const StudyFile& file, int law, const std::vector<std::string>& overrides) const;
};

// Run labels of the two methods: "ED dry <tag>", "hydro wet <tag>".
std::string particleLabel(int law, const std::string& tag);
std::string hydroLabel(int law, const std::string& tag);

}  // namespace granwave
