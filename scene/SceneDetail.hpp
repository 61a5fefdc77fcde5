#pragma once
// Internal to the scene library (not installed, not for other folders): what the parser,
// the validator and the writer share.
#include <map>
#include <string>
#include <string_view>

#include "scene/Scene.hpp"

namespace granwave::detail {

// Where each key of a scene came from, so that errors point at the right place.
struct SceneOrigins {
  std::string file;     // path or "<string>"
  bool parsed = false;  // keys missing from `where` took their defaults (else: built in code)
  std::map<std::string, std::string, std::less<>> where;  // "contact.e" -> "a.toml:12"
  // "a.toml:12: contact.e = 1.5" (or "a.toml: contact.e = 0.9 (default)" when not given).
  std::string describe(std::string_view key, std::string_view value) const;
};

// Ranges, geometry and packing; throws SceneError naming the offending key.
void validateScene(const Scene& scene, const SceneOrigins& origins);

// Shortest text that reads back as the same double, always in TOML float form ("4.0").
std::string tomlNumber(double value);

}  // namespace granwave::detail
