#include "particles/H5mdWriter.hpp"

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "h5/AtomicFile.hpp"
#include "h5/Writeback.hpp"

namespace granwave {
namespace {

// Dirty trajectory bytes between two writebacks: at disk speeds of 100 MB/s or more, an fsync
// then waits a fraction of a second at most.
constexpr std::size_t kWritebackBytes = std::size_t{32} << 20;

using h5::ExtendibleDataset;

// One H5MD time-dependent element: <group>/{step,time,value}.
template <h5::Element V>
struct Series {
  ExtendibleDataset<std::int64_t> step;
  ExtendibleDataset<double> time;
  ExtendibleDataset<V> value;

  void append(std::span<const std::int64_t> steps, std::span<const double> times,
              std::span<const V> values) {
    step.append(steps);
    time.append(times);
    value.append(values);
  }
  void close() {
    step.close();
    time.close();
    value.close();
  }
};

template <h5::Element V>
Series<V> createSeries(h5::File& file, const std::string& group, const h5::Shape& row_shape,
                       std::size_t value_chunk_rows, const std::string& unit,
                       h5::Storage storage = h5::Storage::contiguous) {
  file.createGroup(group);
  Series<V> series{
      file.createExtendible<std::int64_t>(group + "/step", {}, 1024, storage),
      file.createExtendible<double>(group + "/time", {}, 1024, storage),
      file.createExtendible<V>(group + "/value", row_shape, value_chunk_rows, storage)};
  file.writeStringAttribute(group + "/time", "unit", "s");
  file.writeStringAttribute(group + "/value", "unit", unit);
  return series;
}

template <h5::Element V>
Series<V> openSeries(h5::File& file, const std::string& group) {
  return {file.openExtendible<std::int64_t>(group + "/step"),
          file.openExtendible<double>(group + "/time"), file.openExtendible<V>(group + "/value")};
}

std::string authorName(const RunProvenance& provenance) {
  if (!provenance.author.empty()) return provenance.author;
  const char* user = std::getenv("USER");
  return user != nullptr && user[0] != '\0' ? user : "unknown";
}

void writeHeader(h5::File& file, const RunProvenance& provenance) {
  file.createGroup("/h5md");
  file.writeArrayAttribute<std::int64_t>("/h5md", "version", {1, 1});
  file.createGroup("/h5md/author");
  file.writeStringAttribute("/h5md/author", "name", authorName(provenance));
  file.createGroup("/h5md/creator");
  file.writeStringAttribute("/h5md/creator", "name", h5md::kCreatorName);
  file.writeStringAttribute("/h5md/creator", "version", provenance.program_version);
  // The "unit" attributes belong to H5MD's units module, which a file declares here.
  file.createGroup("/h5md/modules/units");
  file.writeArrayAttribute<std::int64_t>("/h5md/modules/units", "version", {1, 0});
  file.writeStringAttribute("/h5md/modules/units", "system", "SI");
}

void writeBoxAttributes(h5::File& file, const BoxInfo& box) {
  file.createGroup(h5md::kBox);
  // MDAnalysis wants a 3D box: the layer is the x-z plane of a slab one diameter thick.
  file.writeAttribute<std::int64_t>(h5md::kBox, "dimension", 3);
  file.writeStringArrayAttribute(
      h5md::kBox, "boundary",
      {box.periodic_x ? "periodic" : "none", "none", box.periodic_z ? "periodic" : "none"});
}

void writeParameters(h5::File& file, const std::string& scene_toml,
                     const RunProvenance& provenance) {
  file.createGroup(h5md::kParameters);
  file.writeStringDataset(h5md::kScene, scene_toml);
  file.createGroup(h5md::kProvenance);
  file.writeStringAttribute(h5md::kProvenance, "program_version", provenance.program_version);
  file.writeStringAttribute(h5md::kProvenance, "command_line", provenance.command_line);
  file.writeAttribute<std::uint64_t>(h5md::kProvenance, "seed", provenance.seed);
}

}  // namespace

struct H5mdWriter::State {
  State(std::string target, BoxInfo box_info, int trajectory_stride)
      : atomic(std::move(target)), box(box_info), stride(trajectory_stride) {}
  State(std::string target, const std::string& continue_from, BoxInfo box_info,
        int trajectory_stride)
      : atomic(std::move(target), continue_from), box(box_info), stride(trajectory_stride) {}

  // Declared first so it is destroyed last: the datasets below close before the
  // unfinished temporary file is deleted.
  h5::AtomicFile atomic;
  BoxInfo box;
  int stride;
  int particles = -1;  // fixed by the first snapshot
  bool finished = false;
  std::size_t records = 0;
  std::size_t frames = 0;
  std::size_t unsynced_bytes = 0;  // trajectory bytes appended since the last writeback

  Series<double> edges, position, velocity, angular_velocity;
  std::vector<Series<double>> reals;
  std::vector<Series<std::uint64_t>> counts;
  Series<std::uint64_t> collisions;

  // Observables are buffered and written a whole chunk at a time: one HDF5 append per
  // 1024 records instead of ~30 per record.
  std::vector<std::int64_t> pending_steps;
  std::vector<double> pending_times;
  std::vector<std::vector<double>> pending_reals;
  std::vector<std::vector<std::uint64_t>> pending_counts;
  std::vector<std::uint64_t> pending_collisions;  // kCollisionColumns per record

  std::vector<double> row;  // one trajectory frame, reused

  h5::File& file() { return atomic.file(); }
  void createObservables();
  void reopenAll();
  void checkShape(const Snapshot& snapshot);
  void bufferObservables(const Snapshot& snapshot);
  void flushObservables();
  void createTrajectories(std::size_t n);
  void writeFrame(const Snapshot& snapshot);
  void closeAll();
};

// The observables, one row per record, compressed (h5::Storage): their steps and times are
// regular and the counters slow, so a run file at 400 phases per cycle shrinks to about a
// fifth (30 to 6.4 MB for 200 cycles of the paper's scene).
void H5mdWriter::State::createObservables() {
  constexpr h5::Storage kStorage = h5::Storage::compressed;
  file().createGroup(h5md::kObservables);
  for (const auto& observable : h5md::kRealObservables) {
    reals.push_back(createSeries<double>(file(), h5md::observableGroup(observable.name), {},
                                         h5md::kObservableChunk, observable.unit, kStorage));
  }
  for (const auto& observable : h5md::kCountObservables) {
    counts.push_back(createSeries<std::uint64_t>(file(), h5md::observableGroup(observable.name), {},
                                                 h5md::kObservableChunk, "1", kStorage));
  }
  collisions =
      createSeries<std::uint64_t>(file(), h5md::kCollisions, {h5md::kCollisionColumns.size()},
                                  h5md::kObservableChunk, "1", kStorage);
  std::vector<std::string> columns;
  for (const auto& column : h5md::kCollisionColumns) columns.emplace_back(column.name);
  file().writeStringArrayAttribute(h5md::kCollisions + "/value", "columns", columns);
  pending_reals.resize(reals.size());
  pending_counts.resize(counts.size());
}

// The datasets of a checkpoint copy, in the order createObservables and createTrajectories
// made them; the counts follow from their rows.
void H5mdWriter::State::reopenAll() {
  h5::File& f = file();
  edges = openSeries<double>(f, h5md::kEdges);
  for (const auto& observable : h5md::kRealObservables)
    reals.push_back(openSeries<double>(f, h5md::observableGroup(observable.name)));
  for (const auto& observable : h5md::kCountObservables)
    counts.push_back(openSeries<std::uint64_t>(f, h5md::observableGroup(observable.name)));
  collisions = openSeries<std::uint64_t>(f, h5md::kCollisions);
  pending_reals.resize(reals.size());
  pending_counts.resize(counts.size());
  records = collisions.step.rows();
  if (f.exists(h5md::kPosition)) {
    position = openSeries<double>(f, h5md::kPosition);
    velocity = openSeries<double>(f, h5md::kVelocity);
    angular_velocity = openSeries<double>(f, h5md::kAngularVelocity);
    frames = position.step.rows();
    particles = static_cast<int>(position.value.rowShape().at(0));
  }
}

void H5mdWriter::State::checkShape(const Snapshot& snapshot) {
  const std::size_t n = snapshot.x.size();
  if (snapshot.z.size() != n || snapshot.vx.size() != n || snapshot.vz.size() != n ||
      snapshot.omega.size() != n) {
    throw std::invalid_argument(atomic.target() + ": snapshot " + std::to_string(snapshot.step) +
                                " has particle vectors of different lengths");
  }
  if (particles >= 0 && static_cast<std::size_t>(particles) != n) {
    throw std::invalid_argument(atomic.target() + ": snapshot " + std::to_string(snapshot.step) +
                                " has " + std::to_string(n) + " particles, earlier ones " +
                                std::to_string(particles));
  }
  particles = static_cast<int>(n);
}

void H5mdWriter::State::bufferObservables(const Snapshot& snapshot) {
  pending_steps.push_back(static_cast<std::int64_t>(snapshot.step));
  pending_times.push_back(snapshot.time);
  for (std::size_t i = 0; i < reals.size(); ++i) {
    pending_reals[i].push_back(h5md::kRealObservables[i].get(snapshot));
  }
  for (std::size_t i = 0; i < counts.size(); ++i) {
    pending_counts[i].push_back(h5md::kCountObservables[i].get(snapshot));
  }
  for (const auto& column : h5md::kCollisionColumns) {
    pending_collisions.push_back(column.get(snapshot));
  }
  ++records;
  if (pending_steps.size() >= h5md::kObservableChunk) flushObservables();
}

void H5mdWriter::State::flushObservables() {
  for (std::size_t i = 0; i < reals.size(); ++i) {
    reals[i].append(pending_steps, pending_times, pending_reals[i]);
    pending_reals[i].clear();
  }
  for (std::size_t i = 0; i < counts.size(); ++i) {
    counts[i].append(pending_steps, pending_times, pending_counts[i]);
    pending_counts[i].clear();
  }
  collisions.append(pending_steps, pending_times, pending_collisions);
  pending_collisions.clear();
  pending_steps.clear();
  pending_times.clear();
}

// Created at the first frame (or at finish) because N is known only then. One frame per
// chunk: a reader loading frame i touches exactly one chunk per quantity.
void H5mdWriter::State::createTrajectories(std::size_t n) {
  position = createSeries<double>(file(), h5md::kPosition, {n, 3}, 1, "m");
  velocity = createSeries<double>(file(), h5md::kVelocity, {n, 3}, 1, "m s-1");
  angular_velocity = createSeries<double>(file(), h5md::kAngularVelocity, {n, 3}, 1, "rad s-1");
}

void H5mdWriter::State::writeFrame(const Snapshot& snapshot) {
  const std::size_t n = static_cast<std::size_t>(particles);
  if (frames == 0) createTrajectories(n);
  const std::int64_t step[] = {static_cast<std::int64_t>(snapshot.step)};
  const double time[] = {snapshot.time};
  const double box_edges[] = {box.width, 0, 0, 0, box.thickness, 0, 0, 0, box.height};
  edges.append(step, time, box_edges);

  row.assign(3 * n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    row[3 * j] = snapshot.x[j];
    row[3 * j + 2] = snapshot.z[j];
  }
  position.append(step, time, row);
  for (std::size_t j = 0; j < n; ++j) {
    row[3 * j] = snapshot.vx[j];
    row[3 * j + 2] = snapshot.vz[j];
  }
  velocity.append(step, time, row);
  row.assign(3 * n, 0.0);
  for (std::size_t j = 0; j < n; ++j) row[3 * j + 1] = snapshot.omega[j];
  angular_velocity.append(step, time, row);
  ++frames;
  // Three rows of 3 n doubles a frame. Writing them back as the run goes keeps the dirty part
  // of the file small, so the fsync of a commit or an interrupt waits for at most that much,
  // however large the run file has grown (docs/commands.md, "Interrupting").
  unsynced_bytes += 9 * n * sizeof(double);
  if (unsynced_bytes >= kWritebackBytes) {
    h5::startWriteback(file());
    unsynced_bytes = 0;
  }
}

void H5mdWriter::State::closeAll() {
  for (Series<double>* series : {&edges, &position, &velocity, &angular_velocity}) {
    series->close();
  }
  for (auto& series : reals) series.close();
  for (auto& series : counts) series.close();
  collisions.close();
}

H5mdWriter::H5mdWriter(std::string path, std::string scene_toml, RunProvenance provenance,
                       BoxInfo box, int trajectory_stride) {
  if (trajectory_stride < 1) {
    throw std::invalid_argument(path + ": trajectory stride must be >= 1, got " +
                                std::to_string(trajectory_stride));
  }
  state_ = std::make_unique<State>(std::move(path), box, trajectory_stride);
  h5::File& file = state_->file();
  writeHeader(file, provenance);
  writeBoxAttributes(file, box);
  state_->edges = createSeries<double>(file, h5md::kEdges, {3, 3}, 256, "m");
  state_->createObservables();
  writeParameters(file, scene_toml, provenance);
}

H5mdWriter::H5mdWriter(std::string path, const std::string& checkpoint_copy, BoxInfo box,
                       int trajectory_stride) {
  if (trajectory_stride < 1) {
    throw std::invalid_argument(path + ": trajectory stride must be >= 1, got " +
                                std::to_string(trajectory_stride));
  }
  state_ = std::make_unique<State>(std::move(path), checkpoint_copy, box, trajectory_stride);
  state_->reopenAll();
}

H5mdWriter::~H5mdWriter() = default;

void H5mdWriter::checkpoint(const std::string& copy_path) {
  State& s = *state_;
  if (s.finished) throw std::logic_error(s.atomic.target() + ": checkpoint() after finish()");
  s.flushObservables();
  s.atomic.copyTo(copy_path);
}

void H5mdWriter::observe(const Snapshot& snapshot) {
  State& s = *state_;
  if (s.finished) throw std::logic_error(s.atomic.target() + ": observe() after finish()");
  s.checkShape(snapshot);
  s.bufferObservables(snapshot);
  if (snapshot.step % static_cast<std::uint64_t>(s.stride) == 0) s.writeFrame(snapshot);
}

void H5mdWriter::finish(bool complete, const std::string& summary,
                        const std::string& final_path_override) {
  State& s = *state_;
  if (s.finished) throw std::logic_error(s.atomic.target() + ": finish() called twice");
  s.flushObservables();
  // Records but no frame yet (every step so far off the stride): still give the readers
  // their (empty) particle groups. With no record at all N is unknown and they stay absent.
  if (s.frames == 0 && s.particles > 0) s.createTrajectories(static_cast<std::size_t>(s.particles));
  h5::File& file = s.file();
  file.writeAttribute<std::int64_t>(h5md::kParameters, "completed", complete ? 1 : 0);
  if (!summary.empty()) file.writeStringAttribute(h5md::kParameters, "summary", summary);
  s.closeAll();
  s.atomic.commitTo(final_path_override.empty() ? s.atomic.target() : final_path_override);
  s.finished = true;
}

void H5mdWriter::writePairImpacts(const PairImpactHistogram& impacts) {
  State& s = *state_;
  if (s.finished || s.file().exists(h5md::kPairImpacts))
    throw std::logic_error(s.atomic.target() + ": pair impacts written after finish() or twice");
  impacts.saveState(s.file(), h5md::kPairImpacts);
}

const std::string& H5mdWriter::path() const { return state_->atomic.target(); }
std::size_t H5mdWriter::recordCount() const { return state_->records; }
std::size_t H5mdWriter::frameCount() const { return state_->frames; }

}  // namespace granwave
