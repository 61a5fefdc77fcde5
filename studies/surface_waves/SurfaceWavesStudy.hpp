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

// The 2D continuum (hydro.dimensions = 2; docs/hydro.md, "The 2D model") beside the
// particles: every variant of `variants` at every Gamma, width and boundary (periodic or side
// walls), the base box's rows, at one frequency, one continuum run per seed (the seed perturbs
// its column masses); the particles at the same points are planned too. Empty `variants`: no
// continuum runs.
struct ContinuumWavesConfig {
  std::vector<int> variants;  // indices into SurfaceWavesConfig::variants
  std::vector<double> widths_d{120}, gammas{4};
  std::vector<std::string> boundaries{"periodic"};  // "periodic", "walls"
  double frequency = 10;
  int cycles = 80;  // the spectrum is taken over the second half, as the particles' transient
  int columns = 0;  // hydro.columns (0: one per 4 d of the width)
  int cells = 40;   // hydro.cells per column
  std::vector<int> seeds{1};
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
  ContinuumWavesConfig continuum;

  std::string label(const SurfaceWavePoint& p) const;
  std::vector<SurfaceWavePoint> onsetPoints() const;
  std::vector<SurfaceWavePoint> widthPoints() const;
  std::vector<SurfaceWavePoint> depthPoints() const;
  // The continuum's points (one per continuum seed) and the particles' at the same drive,
  // box and rows (one per particle seed).
  std::vector<SurfaceWavePoint> continuumPoints(bool particle_seeds = false) const;
  std::vector<SurfaceWavePoint> continuumParticlePoints() const;
  std::string continuumLabel(const SurfaceWavePoint& p) const;
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
  void addContinuumRequests(const StudyFile& f);
  // The scene overrides of a point: its variant's, then box, drive, seed and duration.
  std::vector<std::string> pointOverrides(const SurfaceWavePoint& p, int cycles) const;
  SurfaceWavesConfig c_;
  std::vector<RunRequest> requests_;
};

std::unique_ptr<Study> makeSurfaceWavesStudy(StudyFile& file);

}  // namespace granwave
