#pragma once
// The surface-waves study (docs/studies.md): Faraday-type surface waves measured as waves from
// the space-time spectrum of the layer's surface (coarse_grain/SurfaceWaveSpectrum.hpp).
// Three scans over one set of layer variants (dry, wet, constant e, the readings of the
// paper's text): the onset Gamma_c(f) in a base box; the box width and boundary at one drive
// point (box modes against Faraday waves); the depth against f (the dispersion relation
// lambda / H against f sqrt(H / g)). Beside them the paper's order parameter r_x, with the
// r_x of layers without waves as its noise floor, and each variant's dissipation. This file:
// the study's keys and its runs.
#include <memory>
#include <string>
#include <vector>

#include "studies/contract/Study.hpp"
#include "studies/contract/StudyScenes.hpp"

namespace granwave {

// A layer: one of the two base laws with scene overrides (constant e, a reading).
struct SurfaceWaveVariant {
  std::string name;
  int law = 0;  // kLawNames index
  std::vector<std::string> set;
};

// One run of the study (per seed).
struct SurfaceWavePoint {
  int variant = 0;
  double width_d = 120;
  bool periodic = true;
  int rows = 10;
  double frequency = 10, gamma = 4;
  int seed = 1;
};

struct SurfaceWavesConfig {
  LawScenes scenes;
  std::vector<SurfaceWaveVariant> variants;
  int cycles = 80;  // per run; duration = cycles / f
  std::vector<int> seeds{1, 2};
  int window = 2, blocks = 5;
  // The base box of the onset scan and of r_x.
  double width_d = 120;
  bool periodic = true;
  int rows = 10;
  std::vector<double> frequencies{10, 15, 20}, gammas{2, 3, 4, 5};
  // The width scan: every width with every boundary at one drive point.
  std::vector<double> widths_d{30, 60, 120, 240};
  std::vector<std::string> boundaries{"periodic", "walls"};
  double width_frequency = 10, width_gamma = 4;
  std::vector<int> width_variants;  // indices into variants
  // The depth scan: rows against f at one Gamma.
  std::vector<int> depth_rows{5, 10, 15};
  std::vector<double> depth_frequencies{10, 15, 20};
  double depth_gamma = 4;
  std::vector<int> depth_variants;
  // The dissipation of a variant is read at this Gamma and the first frequency.
  double dissipation_gamma = 3;
  double diameter = 0.002;  // m, of the base scenes

  std::string label(const SurfaceWavePoint& p) const;
  std::vector<SurfaceWavePoint> onsetPoints() const;
  std::vector<SurfaceWavePoint> widthPoints() const;
  std::vector<SurfaceWavePoint> depthPoints() const;
  int variantIndex(const std::string& name) const;  // -1 if absent
};

class SurfaceWavesStudy final : public Study {
 public:
  explicit SurfaceWavesStudy(StudyFile& f);
  std::string title() const override {
    return "Surface waves as waves: onset, wavelength and dispersion, dry against wet";
  }
  std::vector<RunRequest> plan() const override { return requests_; }
  void analyse(const RunSet& runs, h5::File& results, Report& report) const override;

 private:
  void addRequests(const StudyFile& f, const std::vector<SurfaceWavePoint>& points);
  SurfaceWavesConfig c_;
  std::vector<RunRequest> requests_;
};

std::unique_ptr<Study> makeSurfaceWavesStudy(StudyFile& file);

}  // namespace granwave
