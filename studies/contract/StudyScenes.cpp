#include "studies/contract/StudyScenes.hpp"

#include <fmt/format.h>

#include <limits>

#include "scene/SceneParser.hpp"

namespace granwave {

Scene studyScene(const StudyFile& study, const std::string& scene_path,
                 const std::vector<std::string>& overrides) {
  try {
    // A study keeps one frame of positions per drive cycle (it reads the fields). That stride
    // is set before the scene's checks: the file's own (every phase, the paper's scenes) can
    // exceed the positions limit at a study's finer sampling or in a deeper layer.
    std::vector<std::string> all = overrides;
    all.push_back(fmt::format("run.trajectory_stride={}", std::numeric_limits<int>::max()));
    Scene s = parseSceneFile(scene_path, all);
    if (!(s.drive.frequency > 0)) return parseSceneFile(scene_path, overrides);
    s.run.trajectory_stride = s.run.phases_per_cycle;
    try {
      validateScene(s, scene_path);
    } catch (const SceneError& e) {
      throw SceneError(std::string(e.what()) +
                       " (a study keeps one frame of positions per drive cycle: shorten "
                       "run.duration or lower particles.count)");
    }
    return s;
  } catch (const SceneError& e) {
    std::string set;
    for (const std::string& o : overrides) set += (set.empty() ? "" : ", ") + o;
    throw StudyError(fmt::format("{}: scene {}{}: {}", study.path(), scene_path,
                                 set.empty() ? "" : " with " + set, e.what()));
  }
}

LawScenes LawScenes::read(StudyFile& f) {
  LawScenes s;
  s.path[0] = f.scenePath("scenes", "dry", "../scenes/paper-dry.toml");
  s.path[1] = f.scenePath("scenes", "wet", "../scenes/paper-wet.toml");
  s.set = f.strings("scenes", "set", {});
  return s;
}

void LawScenes::loadBase(const StudyFile& f) {
  for (int law = 0; law < kLaws; ++law) base[law] = studyScene(f, path[law], set);
}

Scene LawScenes::scene(const StudyFile& f, int law,
                       const std::vector<std::string>& overrides) const {
  std::vector<std::string> all = set;
  all.insert(all.end(), overrides.begin(), overrides.end());
  return studyScene(f, path[law], all);
}

std::string particleLabel(int law, const std::string& tag) {
  return fmt::format("ED {} {}", kLawNames[law], tag);
}

std::string hydroLabel(int law, const std::string& tag) {
  return fmt::format("hydro {} {}", kLawNames[law], tag);
}

}  // namespace granwave
