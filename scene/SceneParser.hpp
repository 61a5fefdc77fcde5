#pragma once
// Scene files: TOML in SI units, sections and keys named exactly as the fields of Scene
// (docs/scenes.md is the user guide). Parsing fills a default Scene (the paper's values) from
// the file, applies `--set section.key=value` overrides on top, then validates the result.
// Every failure is a SceneError with a one-line message naming the file, the key, the bad
// value and what is valid. sceneToToml writes a complete scene back, so that
// parseSceneString(sceneToToml(s)) == s for every parsed scene s.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/Scene.hpp"

namespace granwave {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads and validates a scene file; `overrides` are "section.key=value" strings whose value
// is a TOML value (a bare word is taken as a string: contact.restitution=wet). The file (or an
// override) must name its restitution law, contact.restitution: every other key has the
// paper's value as default, but an empty or truncated file must not silently become the dry
// scene (docs/scenes.md). Strings (parseSceneString) keep the defaults for every key.
Scene parseSceneFile(const std::string& path, const std::vector<std::string>& overrides = {});

// Same for a scene held in memory; `origin` names it in error messages.
Scene parseSceneString(std::string_view toml, const std::vector<std::string>& overrides = {},
                       std::string_view origin = "<string>");

// The semantic checks parsing runs (ranges, geometry, packing), for scenes built in code.
void validateScene(const Scene& scene, std::string_view origin = "<scene>");

// The complete, resolved scene as TOML: every key, with units and derived values in comments.
std::string sceneToToml(const Scene& scene);

}  // namespace granwave
