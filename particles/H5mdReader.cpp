#include "particles/H5mdReader.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "h5/File.hpp"
#include "h5/H5Error.hpp"

namespace granwave {
namespace {

using h5::H5Error;
using h5::kAnyExtent;

struct ElementShape {
  std::size_t count;  // rows of step, time and value
  h5::Shape value;    // full shape of value
};

// Checks one time-dependent element: step [n], time [n], value [n][row_shape...].
ElementShape checkElement(const h5::File& file, const std::string& group,
                          const h5::Shape& row_shape) {
  for (const char* part : {"/step", "/time", "/value"}) {
    if (!file.isDataset(group + part)) {
      throw H5Error(file.name() + ": no dataset " + group + part + " (not a granwave run?)");
    }
  }
  const h5::Shape value = file.shape(group + "/value");
  if (value.empty() || value.size() != row_shape.size() + 1 ||
      !std::equal(
          row_shape.begin(), row_shape.end(), value.begin() + 1,
          [](std::size_t want, std::size_t got) { return want == kAnyExtent || want == got; })) {
    h5::Shape expected{kAnyExtent};
    expected.insert(expected.end(), row_shape.begin(), row_shape.end());
    throw H5Error(file.name() + ": " + group + "/value has shape " + h5::shapeString(value) +
                  ", expected " + h5::shapeString(expected));
  }
  for (const char* part : {"/step", "/time"}) {
    const h5::Shape shape = file.shape(group + part);
    if (shape != h5::Shape{value[0]}) {
      throw H5Error(file.name() + ": " + group + part + " has shape " + h5::shapeString(shape) +
                    ", but " + group + "/value has " + std::to_string(value[0]) + " rows");
    }
  }
  return {value[0], value};
}

void requireSameCount(const h5::File& file, const std::string& group, std::size_t count,
                      std::size_t expected, const std::string& reference) {
  if (count != expected) {
    throw H5Error(file.name() + ": " + group + " has " + std::to_string(count) + " rows, but " +
                  reference + " has " + std::to_string(expected));
  }
}

}  // namespace

struct H5mdReader::State {
  explicit State(const std::string& path) : file(h5::File::openReadOnly(path)) {}

  h5::File file;
  std::string scene;
  BoxInfo box;
  RunProvenance provenance;
  bool completed = false;
  std::string summary;
  std::size_t frames = 0;
  std::size_t records = 0;
  int particles = 0;
  std::vector<std::int64_t> record_steps;  // to find the record of a frame

  void checkCreator();
  void checkTrajectory();
  void checkObservables();
  void readParameters();
  void readBox();
};

void H5mdReader::State::checkCreator() {
  const std::string& name = file.name();
  if (!file.isGroup("/h5md")) throw H5Error(name + ": not an H5MD file (no /h5md group)");
  const std::vector<std::int64_t> version =
      file.readArrayAttribute<std::int64_t>("/h5md", "version");
  if (version.size() != 2 || version[0] != 1) {
    throw H5Error(name + ": unsupported H5MD version (granwave reads 1.x)");
  }
  if (!file.hasAttribute("/h5md/creator", "name")) {
    throw H5Error(name + ": H5MD file without /h5md/creator name, not a granwave run");
  }
  const std::string creator = file.readStringAttribute("/h5md/creator", "name");
  if (creator != h5md::kCreatorName) {
    throw H5Error(name + ": H5MD file written by '" + creator + "', not by granwave");
  }
}

void H5mdReader::State::checkTrajectory() {
  const ElementShape edges = checkElement(file, h5md::kEdges, {3, 3});
  // A run stopped before its first snapshot has no particle groups (their shape needs N).
  if (edges.count == 0 && !file.exists(h5md::kPosition)) return;
  const ElementShape position = checkElement(file, h5md::kPosition, {kAnyExtent, 3});
  frames = position.count;
  particles = static_cast<int>(position.value[1]);
  requireSameCount(file, h5md::kEdges, edges.count, frames, h5md::kPosition);
  for (const std::string& group : {h5md::kVelocity, h5md::kAngularVelocity}) {
    const ElementShape element = checkElement(file, group, {position.value[1], 3});
    requireSameCount(file, group, element.count, frames, h5md::kPosition);
  }
}

void H5mdReader::State::checkObservables() {
  const std::string first = h5md::observableGroup(h5md::kRealObservables[0].name);
  records = checkElement(file, first, {}).count;
  auto check = [&](const char* name) {
    const std::string group = h5md::observableGroup(name);
    requireSameCount(file, group, checkElement(file, group, {}).count, records, first);
  };
  for (const auto& observable : h5md::kRealObservables)
    if (!observable.optional || file.exists(h5md::observableGroup(observable.name)))
      check(observable.name);
  for (const auto& observable : h5md::kCountObservables) check(observable.name);
  const std::size_t kinds = h5md::kCollisionColumns.size();
  requireSameCount(file, h5md::kCollisions, checkElement(file, h5md::kCollisions, {kinds}).count,
                   records, first);
  std::vector<std::string> expected;
  for (const auto& column : h5md::kCollisionColumns) expected.emplace_back(column.name);
  if (file.readStringArrayAttribute(h5md::kCollisions + "/value", "columns") != expected) {
    throw H5Error(file.name() + ": attribute columns of " + h5md::kCollisions +
                  "/value does not name pair, wall, tc_elastic, rests");
  }
  record_steps = file.readDataset<std::int64_t>(first + "/step");
  if (!std::is_sorted(record_steps.begin(), record_steps.end())) {
    throw H5Error(file.name() + ": " + first + "/step is not increasing");
  }
}

void H5mdReader::State::readParameters() {
  if (!file.isDataset(h5md::kScene)) {
    throw H5Error(file.name() + ": no dataset " + h5md::kScene + " (not a granwave run?)");
  }
  scene = file.readStringDataset(h5md::kScene);
  if (file.hasAttribute(h5md::kParameters, "completed")) {
    completed = file.readAttribute<std::int64_t>(h5md::kParameters, "completed") == 1;
  }
  if (file.hasAttribute(h5md::kParameters, "summary")) {
    summary = file.readStringAttribute(h5md::kParameters, "summary");
  }
  const std::string& p = h5md::kProvenance;
  if (file.hasAttribute(p, "program_version")) {
    provenance.program_version = file.readStringAttribute(p, "program_version");
  }
  if (file.hasAttribute(p, "command_line")) {
    provenance.command_line = file.readStringAttribute(p, "command_line");
  }
  if (file.hasAttribute(p, "seed")) provenance.seed = file.readAttribute<std::uint64_t>(p, "seed");
  if (file.hasAttribute("/h5md/author", "name")) {
    provenance.author = file.readStringAttribute("/h5md/author", "name");
  }
}

void H5mdReader::State::readBox() {
  if (file.readAttribute<std::int64_t>(h5md::kBox, "dimension") != 3) {
    throw H5Error(file.name() + ": " + h5md::kBox + " is not 3-dimensional");
  }
  const std::vector<std::string> boundary = file.readStringArrayAttribute(h5md::kBox, "boundary");
  if (boundary.size() != 3) {
    throw H5Error(file.name() + ": attribute boundary of " + h5md::kBox + " has " +
                  std::to_string(boundary.size()) + " entries, expected 3");
  }
  box.periodic_x = boundary[0] == "periodic";
  box.periodic_z = boundary[2] == "periodic";
  if (frames > 0) {
    const std::vector<double> edges = file.readRows<double>(h5md::kEdges + "/value", 0, 1);
    box.width = edges[0];
    box.thickness = edges[4];
    box.height = edges[8];
  }
}

H5mdReader::H5mdReader(const std::string& path) : state_(std::make_unique<State>(path)) {
  State& s = *state_;
  s.checkCreator();
  s.checkTrajectory();
  s.checkObservables();
  s.readParameters();
  s.readBox();
}

H5mdReader::~H5mdReader() = default;
H5mdReader::H5mdReader(H5mdReader&&) noexcept = default;
H5mdReader& H5mdReader::operator=(H5mdReader&&) noexcept = default;

const std::string& H5mdReader::path() const { return state_->file.name(); }
const std::string& H5mdReader::sceneToml() const { return state_->scene; }
const BoxInfo& H5mdReader::box() const { return state_->box; }
const RunProvenance& H5mdReader::provenance() const { return state_->provenance; }
bool H5mdReader::completed() const { return state_->completed; }
const std::string& H5mdReader::summary() const { return state_->summary; }
std::size_t H5mdReader::frameCount() const { return state_->frames; }
std::size_t H5mdReader::recordCount() const { return state_->records; }
int H5mdReader::particleCount() const { return state_->particles; }

Snapshot H5mdReader::frame(std::size_t i) const {
  const State& s = *state_;
  if (i >= s.frames) {
    throw std::out_of_range(s.file.name() + ": frame " + std::to_string(i) + " of " +
                            std::to_string(s.frames));
  }
  Snapshot snapshot;
  snapshot.step = static_cast<std::uint64_t>(
      s.file.readRows<std::int64_t>(h5md::kPosition + "/step", i, 1).front());
  snapshot.time = s.file.readRows<double>(h5md::kPosition + "/time", i, 1).front();

  const std::size_t n = static_cast<std::size_t>(s.particles);
  const std::vector<double> position = s.file.readRows<double>(h5md::kPosition + "/value", i, 1);
  const std::vector<double> velocity = s.file.readRows<double>(h5md::kVelocity + "/value", i, 1);
  const std::vector<double> angular =
      s.file.readRows<double>(h5md::kAngularVelocity + "/value", i, 1);
  snapshot.x.resize(n);
  snapshot.z.resize(n);
  snapshot.vx.resize(n);
  snapshot.vz.resize(n);
  snapshot.omega.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    snapshot.x[j] = position[3 * j];
    snapshot.z[j] = position[3 * j + 2];
    snapshot.vx[j] = velocity[3 * j];
    snapshot.vz[j] = velocity[3 * j + 2];
    snapshot.omega[j] = angular[3 * j + 1];
  }

  const auto& steps = s.record_steps;
  const auto found =
      std::lower_bound(steps.begin(), steps.end(), static_cast<std::int64_t>(snapshot.step));
  if (found != steps.end() && *found == static_cast<std::int64_t>(snapshot.step)) {
    const std::size_t r = static_cast<std::size_t>(found - steps.begin());
    for (const auto& observable : h5md::kRealObservables) {
      const std::string value = h5md::observableGroup(observable.name) + "/value";
      observable.set(snapshot, observable.optional && !s.file.exists(value)
                                   ? std::numeric_limits<double>::quiet_NaN()
                                   : s.file.readRows<double>(value, r, 1).front());
    }
    for (const auto& observable : h5md::kCountObservables) {
      const std::string value = h5md::observableGroup(observable.name) + "/value";
      observable.set(snapshot, s.file.readRows<std::uint64_t>(value, r, 1).front());
    }
    const std::vector<std::uint64_t> counts =
        s.file.readRows<std::uint64_t>(h5md::kCollisions + "/value", r, 1);
    for (std::size_t c = 0; c < h5md::kCollisionColumns.size(); ++c) {
      h5md::kCollisionColumns[c].set(snapshot, counts[c]);
    }
  }
  return snapshot;
}

TimeSeries H5mdReader::observable(const std::string& name) const {
  const h5::File& file = state_->file;
  // "collisions/<kind>" is a column of the collisions table.
  const std::string prefix = "collisions/";
  const bool column = name.rfind(prefix, 0) == 0;
  const std::string group = h5md::observableGroup(column ? "collisions" : name);
  const ElementShape shape =
      checkElement(file, group, column ? h5::Shape{kAnyExtent} : h5::Shape{});
  TimeSeries series;
  series.step = file.readDataset<std::int64_t>(group + "/step", {shape.count});
  series.time = file.readDataset<double>(group + "/time", {shape.count});
  if (!column) {
    series.value = file.readDataset<double>(group + "/value", {shape.count});
    return series;
  }
  const std::vector<std::string> columns =
      file.readStringArrayAttribute(group + "/value", "columns");
  const auto found = std::find(columns.begin(), columns.end(), name.substr(prefix.size()));
  if (found == columns.end() || columns.size() != shape.value[1]) {
    throw H5Error(file.name() + ": no column " + name.substr(prefix.size()) + " in " + group +
                  "/value");
  }
  const std::size_t c = static_cast<std::size_t>(found - columns.begin());
  const std::vector<double> table = file.readDataset<double>(group + "/value");
  series.value.resize(shape.count);
  for (std::size_t r = 0; r < shape.count; ++r) series.value[r] = table[r * columns.size() + c];
  return series;
}

}  // namespace granwave
