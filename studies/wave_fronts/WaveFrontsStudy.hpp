#pragma once
// The wave-fronts study (docs/studies.md): the paper's wave-propagation section (Sec. IV,
// Figs. 4, 5, 6) from the particles and from the hydro solver, the cost of each against its
// accuracy, where each method fails, and the simplest model that reproduces the particles.
// The plan (runs) is built in WaveFrontsStudy.cpp, the analysis in WaveFrontsReport.cpp.
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "studies/framework/ImpactFronts.hpp"
#include "studies/framework/Study.hpp"

namespace granwave {

struct WaveFrontsConfig {
  std::string dry_path, wet_path;
  std::vector<std::string> set;
  double duration = 30;
  std::vector<int> seeds{1, 2, 3};
  int window = 2, blocks = 5;
  std::vector<double> profile_phases{0.88, 0.90, 0.92, 0.94, 0.96};
  double sweep_duration = 20;
  std::vector<int> counts{150, 300, 450, 600};
  std::vector<double> stokes{20, 40, 80}, e_inf{0.8, 0.91, 0.95};
  std::vector<double> cost_durations{7.5, 15, 30, 60};
  std::vector<int> cost_cells{50, 100, 200, 400, 800};
  std::vector<double> cost_rtol{1e-3, 1e-4, 1e-5};
  std::vector<double> fail_gammas{1.5, 2.5, 4, 6, 8};
  double fail_duration = 5;
  std::vector<int> fail_cells{100, 400};
  std::vector<double> fail_rtol{1e-2, 1e-4};
  // The soft-sphere DEM alternative (LAMMPS; about 70 s per 15 s run here): "auto" runs it
  // when Debian's lammps is installed, "yes" requires it (installing it with install = true),
  // "no" leaves it out.
  std::string lammps_mode = "auto";
  bool lammps = false, lammps_install = false;
  std::string lammps_executable = "lmp", lammps_deck;
  double lammps_duration = 15;
  int lammps_seed = 1;
};

inline constexpr const char* kLawNames[2] = {"dry", "wet"};

class WaveFrontsStudy final : public Study {
 public:
  explicit WaveFrontsStudy(StudyFile& f);
  std::string title() const override {
    return "Wave fronts in vibrated dry and wet layers: particles against the continuum";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  void addLammps(StudyFile& f);
  void add(RunKind kind, int law, const std::string& label, std::vector<std::string> overrides,
           double duration);
  std::string edLabel(int law, const std::string& tag) const {
    return fmt::format("ED {} {}", kLawNames[law], tag);
  }
  std::string hydroLabel(int law, const std::string& tag) const {
    return fmt::format("hydro {} {}", kLawNames[law], tag);
  }

  void paperSection(const RunSet& runs, h5::File& f, Report& report) const;
  void sweepSections(const RunSet& runs, h5::File& f, Report& report) const;
  void costSection(const RunSet& runs, h5::File& f, Report& report) const;
  void failureSection(const RunSet& runs, h5::File& f, Report& report) const;
  void modelSection(const RunSet& runs, h5::File& f, Report& report) const;
  void lammpsSection(const RunSet& runs, h5::File& f, Report& report) const;

  const StudyFile* file_;
  WaveFrontsConfig c_;
  Scene base_[2];
  double e_eff_[2] = {0, 0};
  std::vector<RunRequest> requests_;
  mutable ImpactFronts ed_paper_[2];  // filled by paperSection, used by the later sections
  mutable std::string summary_;
};

std::unique_ptr<Study> makeWaveFrontsStudy(StudyFile& file);

}  // namespace granwave
