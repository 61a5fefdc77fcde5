#pragma once
// `granwave fields RUN.h5 [-o FIELDS.h5] [--period auto|P] [--blocks B] [--discard auto|N]`:
// phase-averaged fields, profiles and wave fronts of a recorded run.
#include <string>

namespace CLI {
class App;
}

namespace granwave {

struct FieldsOptions {
  std::string run_path;
  std::string output;  // default: <run>.fields.h5
  std::string period = "auto";
  int blocks = 5;
  std::string discard = "auto";
  double front_threshold = 0.5;  // T~_g / T0 of a front (paper: 0.5)
  bool state_fields = false;     // also average the fields per layer state (/states)
};

void addFieldsCommand(CLI::App& app, FieldsOptions& options);
int runFields(const FieldsOptions& options);

}  // namespace granwave
