#include "studies/surface_waves/SurfaceWavesStudy.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "studies/statistics/Measurement.hpp"
#include "studies/surface_waves/SurfaceWavesAnalysis.hpp"
#include "studies/surface_waves/SurfaceWavesReport.hpp"

namespace granwave {

namespace {

// "a=1; b=2" -> {"a=1", "b=2"} (blanks around each override dropped).
std::vector<std::string> splitOverrides(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    std::string item = text.substr(start, end - start);
    const auto first = item.find_first_not_of(' ');
    const auto last = item.find_last_not_of(' ');
    if (first != std::string::npos) out.push_back(item.substr(first, last - first + 1));
    start = end + 1;
  }
  return out;
}

std::vector<SurfaceWaveVariant> readVariants(StudyFile& f) {
  const auto names = f.strings("variants", "names", {"dry", "wet"});
  const auto laws = f.strings("variants", "laws", {"dry", "wet"});
  const auto sets = f.strings("variants", "set", std::vector<std::string>(names.size(), ""));
  if (names.empty()) f.fail("variants", "names", "expected at least one variant");
  if (laws.size() != names.size() || sets.size() != names.size())
    f.fail("variants", "laws", "names, laws and set must have one entry per variant");
  std::vector<SurfaceWaveVariant> v;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!seen.insert(names[i]).second)
      f.fail("variants", "names", "variant '" + names[i] + "' is listed twice");
    int law = -1;
    for (int k = 0; k < kLaws; ++k)
      if (laws[i] == kLawNames[k]) law = k;
    if (law < 0) f.fail("variants", "laws", "'" + laws[i] + "': valid laws are dry, wet");
    v.push_back({names[i], law, splitOverrides(sets[i])});
  }
  return v;
}

std::vector<int> variantList(StudyFile& f, const std::string& section, const SurfaceWavesConfig& c,
                             std::vector<std::string> fallback) {
  std::vector<int> out;
  for (const std::string& name : f.strings(section, "variants", std::move(fallback))) {
    const int i = c.variantIndex(name);
    if (i < 0) f.fail(section, "variants", "'" + name + "' is not a name of [variants]");
    out.push_back(i);
  }
  return out;
}

void requirePositive(StudyFile& f, const char* section, const char* key,
                     const std::vector<double>& v) {
  if (v.empty()) f.fail(section, key, "expected at least one value");
  for (double x : v)
    if (!(x > 0)) f.fail(section, key, "expected positive values");
}

// The onset is bracketed between neighbouring Gamma of the list (SurfaceWaveOnset.hpp).
void requireAscending(StudyFile& f, const char* section, const char* key,
                      const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1])) f.fail(section, key, "expected increasing values");
}

void requireBoundaries(StudyFile& f, const char* section, const std::vector<std::string>& v) {
  if (v.empty()) f.fail(section, "boundaries", "expected at least one of periodic, walls");
  for (const std::string& b : v)
    if (b != "periodic" && b != "walls")
      f.fail(section, "boundaries", "'" + b + "': valid boundaries are periodic, walls");
}

void readScans(StudyFile& f, SurfaceWavesConfig& c) {
  c.width_d = f.number("grid", "width", c.width_d);
  c.periodic = f.boolean("grid", "periodic", c.periodic);
  c.rows = f.integer("grid", "rows", c.rows);
  c.frequencies = f.numbers("grid", "frequencies", c.frequencies);
  c.gammas = f.numbers("grid", "gammas", c.gammas);
  c.widths_d = f.numbers("widths", "widths", c.widths_d);
  c.boundaries = f.strings("widths", "boundaries", c.boundaries);
  c.width_frequency = f.number("widths", "frequency", c.width_frequency);
  c.width_gamma = f.number("widths", "gamma", c.width_gamma);
  c.width_variants = variantList(f, "widths", c, {c.variants.front().name});
  c.depth_rows = f.integers("depths", "rows", c.depth_rows);
  c.depth_frequencies = f.numbers("depths", "frequencies", c.depth_frequencies);
  c.depth_gamma = f.number("depths", "gamma", c.depth_gamma);
  c.depth_variants = variantList(f, "depths", c, {c.variants.front().name});
  c.dissipation_gamma = f.number("dissipation", "gamma", c.dissipation_gamma);
  requirePositive(f, "grid", "frequencies", c.frequencies);
  requirePositive(f, "grid", "gammas", c.gammas);
  requireAscending(f, "grid", "gammas", c.gammas);
  requirePositive(f, "widths", "widths", c.widths_d);
  requirePositive(f, "depths", "frequencies", c.depth_frequencies);
  for (double w : c.widths_d)
    if (std::abs(w - std::round(w)) > 1e-9) f.fail("widths", "widths", "widths are whole d");
  if (c.rows < 1) f.fail("grid", "rows", "expected at least 1 row");
  for (int r : c.depth_rows)
    if (r < 1) f.fail("depths", "rows", "expected at least 1 row");
  requireBoundaries(f, "widths", c.boundaries);
}

// [continuum]: absent or without variants, no continuum runs.
void readContinuum(StudyFile& f, SurfaceWavesConfig& c) {
  ContinuumWavesConfig& k = c.continuum;
  k.variants = variantList(f, "continuum", c, {});
  k.widths_d = f.numbers("continuum", "widths", {c.width_d});
  k.boundaries = f.strings("continuum", "boundaries", k.boundaries);
  k.gammas = f.numbers("continuum", "gammas", k.gammas);
  k.frequency = f.number("continuum", "frequency", c.frequencies.front());
  k.cycles = f.integer("continuum", "cycles", k.cycles);
  k.columns = f.integer("continuum", "columns", k.columns);
  k.cells = f.integer("continuum", "cells", k.cells);
  k.seeds = f.integers("continuum", "seeds", k.seeds);
  if (k.variants.empty()) {
    if (f.hasSection("continuum"))
      f.fail("continuum", "variants",
             "expected at least one variant of [variants] (leave out [continuum] for no "
             "continuum runs)");
    return;
  }
  requirePositive(f, "continuum", "widths", k.widths_d);
  requireBoundaries(f, "continuum", k.boundaries);
  requireAscending(f, "continuum", "gammas", k.gammas);
  requirePositive(f, "continuum", "gammas", k.gammas);
  if (!(k.frequency > 0)) f.fail("continuum", "frequency", "expected a positive frequency");
  for (double w : k.widths_d)
    if (std::abs(w - std::round(w)) > 1e-9) f.fail("continuum", "widths", "widths are whole d");
  // The spectrum is taken over the run's second half in windows of 10 cycles, two of them
  // from 40 cycles on (a shorter run's windows are shorter: surfaceWindowCycles), as the
  // particles' are.
  if (k.cycles < 40)
    f.fail("continuum", "cycles",
           "expected at least 40 cycles (windows of 10 cycles in the second half, as the "
           "particles')");
  if (k.columns < 0) f.fail("continuum", "columns", "expected 0 (one per 4 d) or more columns");
  if (k.cells < 4) f.fail("continuum", "cells", "expected at least 4 cells per column");
  if (k.seeds.empty() || std::set<int>(k.seeds.begin(), k.seeds.end()).size() != k.seeds.size())
    f.fail("continuum", "seeds", "expected distinct seeds");
}

}  // namespace

int SurfaceWavesConfig::variantIndex(const std::string& name) const {
  for (std::size_t i = 0; i < variants.size(); ++i)
    if (variants[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string SurfaceWavesConfig::label(const SurfaceWavePoint& p) const {
  return fmt::format("ED {} W={} {} rows={} f={} Gamma={} seed={}", variants[p.variant].name,
                     formatCompact(p.width_d), p.periodic ? "periodic" : "walls", p.rows,
                     formatCompact(p.frequency), formatCompact(p.gamma), p.seed);
}

std::vector<SurfaceWavePoint> SurfaceWavesConfig::onsetPoints() const {
  std::vector<SurfaceWavePoint> out;
  for (std::size_t v = 0; v < variants.size(); ++v)
    for (double f : frequencies)
      for (double g : gammas)
        for (int s : seeds) out.push_back({static_cast<int>(v), width_d, periodic, rows, f, g, s});
  return out;
}

std::vector<SurfaceWavePoint> SurfaceWavesConfig::widthPoints() const {
  std::vector<SurfaceWavePoint> out;
  for (int v : width_variants)
    for (const std::string& b : boundaries)
      for (double w : widths_d)
        for (int s : seeds)
          out.push_back({v, w, b == "periodic", rows, width_frequency, width_gamma, s});
  return out;
}

std::vector<SurfaceWavePoint> SurfaceWavesConfig::depthPoints() const {
  std::vector<SurfaceWavePoint> out;
  for (int v : depth_variants)
    for (int r : depth_rows)
      for (double f : depth_frequencies)
        for (int s : seeds) out.push_back({v, width_d, periodic, r, f, depth_gamma, s});
  return out;
}

std::vector<SurfaceWavePoint> SurfaceWavesConfig::continuumPoints(bool particle_seeds) const {
  std::vector<SurfaceWavePoint> boxes;  // seed unset
  for (int v : continuum.variants)
    for (const std::string& b : continuum.boundaries)
      for (double w : continuum.widths_d)
        boxes.push_back({v, w, b == "periodic", rows, continuum.frequency, 0, 0});
  std::vector<SurfaceWavePoint> out;
  for (const SurfaceWavePoint& box : boxes)
    for (double g : continuum.gammas)
      for (int s : particle_seeds ? seeds : continuum.seeds)
        out.push_back({box.variant, box.width_d, box.periodic, rows, box.frequency, g, s});
  return out;
}

std::vector<SurfaceWavePoint> SurfaceWavesConfig::continuumParticlePoints() const {
  return continuumPoints(true);
}

std::string SurfaceWavesConfig::continuumLabel(const SurfaceWavePoint& p) const {
  return fmt::format("2D continuum {} W={} {} rows={} f={} Gamma={} seed={}",
                     variants[p.variant].name, formatCompact(p.width_d),
                     p.periodic ? "periodic" : "walls", p.rows, formatCompact(p.frequency),
                     formatCompact(p.gamma), p.seed);
}

SurfaceWavesStudy::SurfaceWavesStudy(StudyFile& f) {
  c_.scenes = LawScenes::read(f);
  c_.variants = readVariants(f);
  c_.cycles = f.integer("particles", "cycles", c_.cycles);
  c_.seeds = f.integers("particles", "seeds", c_.seeds);
  c_.window = f.integer("particles", "window_cycles", c_.window);
  c_.blocks = f.integer("particles", "blocks", c_.blocks);
  if (c_.cycles < 40)
    f.fail("particles", "cycles",
           "expected at least 40 cycles (the transient, then windows of 10 cycles for the "
           "spectrum's errors)");
  if (c_.seeds.empty() || std::set<int>(c_.seeds.begin(), c_.seeds.end()).size() != c_.seeds.size())
    f.fail("particles", "seeds", "expected distinct seeds");
  if (c_.blocks < 2) f.fail("particles", "blocks", "expected at least 2 blocks");
  readScans(f, c_);
  readContinuum(f, c_);
  c_.scenes.loadBase(f);
  c_.diameter = c_.scenes.base[0].particles.diameter;
  addRequests(f, c_.onsetPoints());
  addRequests(f, c_.widthPoints());
  addRequests(f, c_.depthPoints());
  addRequests(f, c_.continuumParticlePoints());
  addContinuumRequests(f);
}

std::vector<std::string> SurfaceWavesStudy::pointOverrides(const SurfaceWavePoint& p,
                                                           int cycles) const {
  // The paper's box keeps about 21 d of free height above its 10 rows; so does every depth.
  const double height_d = 30.0 + 0.5 * std::sqrt(3.0) * (p.rows - 10);
  std::vector<std::string> set = c_.variants[p.variant].set;
  const int count = static_cast<int>(std::lround(p.width_d)) * p.rows;
  set.push_back(fmt::format("particles.count={}", count));
  set.push_back(fmt::format("container.width={}", formatCompact(p.width_d * c_.diameter)));
  set.push_back(fmt::format("container.height={}", formatCompact(height_d * c_.diameter)));
  set.push_back(fmt::format("container.periodic_x={}", p.periodic ? "true" : "false"));
  set.push_back(fmt::format("drive.frequency={}", formatCompact(p.frequency)));
  set.push_back(fmt::format("drive.gamma={}", formatCompact(p.gamma)));
  set.push_back(fmt::format("run.seed={}", p.seed));
  set.push_back(fmt::format("run.duration={}", formatCompact(cycles / p.frequency)));
  return set;
}

void SurfaceWavesStudy::addContinuumRequests(const StudyFile& f) {
  const ContinuumWavesConfig& k = c_.continuum;
  for (const SurfaceWavePoint& p : c_.continuumPoints()) {
    std::vector<std::string> set = pointOverrides(p, k.cycles);
    set.push_back(fmt::format("hydro.dimensions={}", 2));
    set.push_back(fmt::format("hydro.columns={}", k.columns));
    set.push_back(fmt::format("hydro.cells={}", k.cells));
    requests_.push_back(runRequest(RunKind::Hydro, c_.continuumLabel(p),
                                   c_.scenes.scene(f, c_.variants[p.variant].law, set)));
  }
}

void SurfaceWavesStudy::addRequests(const StudyFile& f,
                                    const std::vector<SurfaceWavePoint>& points) {
  for (const SurfaceWavePoint& p : points) {
    const std::string label = c_.label(p);
    bool known = false;
    for (const RunRequest& q : requests_) known = known || q.label == label;
    if (known) continue;  // a point shared by two scans runs once
    const std::vector<std::string> set = pointOverrides(p, c_.cycles);
    RunRequest q =
        runRequest(RunKind::Particles, label, c_.scenes.scene(f, c_.variants[p.variant].law, set));
    q.window_cycles = c_.window;
    q.blocks = c_.blocks;
    requests_.push_back(std::move(q));
  }
}

void SurfaceWavesStudy::analyse(const RunSet& runs, h5::File& results, Report& report) const {
  const SurfaceWavesResults r = analyseSurfaceWavesStudy(c_, runs);
  writeSurfaceWavesResults(results, r);
  reportSurfaceWaves(c_, r, report);
}

std::unique_ptr<Study> makeSurfaceWavesStudy(StudyFile& file) {
  return std::make_unique<SurfaceWavesStudy>(file);
}

}  // namespace granwave
