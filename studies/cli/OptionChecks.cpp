#include "studies/cli/OptionChecks.hpp"

#include <cmath>
#include <string>

#include "files/OutputPath.hpp"

namespace granwave {

CLI::Validator regularInputFile() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        try {
          files::requireInputFile(path);
        } catch (const files::PathError& e) {
          return e.what();
        }
        return {};
      },
      "FILE", "REGULAR_FILE");
}

CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        if (CLI::detail::lexical_cast(text, value) && std::isfinite(value)) return {};
        return "'" + text + "' is not a finite number";
      },
      "", "FINITE");
}

}  // namespace granwave
