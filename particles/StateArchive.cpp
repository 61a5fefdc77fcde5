#include "particles/StateArchive.hpp"

#include <cstdint>
#include <functional>

#include "h5/H5Error.hpp"

namespace granwave {
namespace {

// A new field in these structs must be added to the archive too, or a restart would lose
// it silently; these sizes make that a compile error.
static_assert(sizeof(ParticleState) == 88, "ParticleState changed: update StateArchive");
static_assert(sizeof(Event) == 24, "Event changed: update StateArchive");
static_assert(sizeof(Observables) == 10 * sizeof(double) + 5 * sizeof(std::uint64_t),
              "Observables changed: update StateArchive");

constexpr std::size_t kObservableReals = 10, kObservableCounts = 5;

std::vector<double> realsOf(const Observables& o) {
  return {o.center_of_mass_height,
          o.kinetic_energy,
          o.rotational_energy,
          o.potential_energy,
          o.dissipated_energy,
          o.wall_work,
          o.pressure,
          o.pair_impact_energy,
          o.pair_impact_loss,
          o.wall_dissipated_energy};
}

std::vector<std::uint64_t> countsOf(const Observables& o) {
  return {o.collisions.pair, o.collisions.wall, o.collisions.tc_elastic, o.collisions.rests,
          o.events};
}

Observables observablesFrom(const double* r, const std::uint64_t* c) {
  Observables o;
  o.center_of_mass_height = r[0];
  o.kinetic_energy = r[1];
  o.rotational_energy = r[2];
  o.potential_energy = r[3];
  o.dissipated_energy = r[4];
  o.wall_work = r[5];
  o.pressure = r[6];
  o.pair_impact_energy = r[7];
  o.pair_impact_loss = r[8];
  o.wall_dissipated_energy = r[9];
  o.collisions.pair = c[0];
  o.collisions.wall = c[1];
  o.collisions.tc_elastic = c[2];
  o.collisions.rests = c[3];
  o.events = c[4];
  return o;
}

// One column of a vector of structs, stored as a 1D dataset of type T.
template <h5::Element T, class Item, class Get>
void writeColumn(h5::File& file, const std::string& path, const std::vector<Item>& items, Get get) {
  std::vector<T> column;
  column.reserve(items.size());
  for (const Item& item : items) column.push_back(static_cast<T>(get(item)));
  file.writeDataset(path, column, {column.size()});
}

template <h5::Element T>
std::vector<T> readColumn(const h5::File& file, const std::string& path, std::size_t n) {
  return file.readDataset<T>(path, {n});
}

std::vector<int> toInts(const std::vector<std::int64_t>& v) { return {v.begin(), v.end()}; }
std::vector<std::int64_t> toInt64(const std::vector<int>& v) { return {v.begin(), v.end()}; }

void writeEvents(h5::File& file, const std::string& group, const std::vector<Event>& events) {
  const std::string e = group + "/";
  file.createGroup(group);
  writeColumn<double>(file, e + "time", events, [](const Event& q) { return q.time; });
  writeColumn<std::uint64_t>(file, e + "kind", events,
                             [](const Event& q) { return static_cast<int>(q.kind); });
  writeColumn<std::int64_t>(file, e + "partner", events, [](const Event& q) { return q.partner; });
  writeColumn<std::uint64_t>(file, e + "partner_counter", events,
                             [](const Event& q) { return q.partner_counter; });
}

std::vector<Event> readEvents(const h5::File& file, const std::string& group, std::size_t n) {
  const std::string e = group + "/";
  const auto time = readColumn<double>(file, e + "time", n);
  const auto kind = readColumn<std::uint64_t>(file, e + "kind", n),
             partner_counter = readColumn<std::uint64_t>(file, e + "partner_counter", n);
  const auto partner = readColumn<std::int64_t>(file, e + "partner", n);
  std::vector<Event> events(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (kind[i] > static_cast<std::uint64_t>(EventKind::TakeOff))
      throw h5::H5Error(file.name() + ": " + e + "kind holds " + std::to_string(kind[i]) +
                        ", valid are 0-4");
    events[i] = {time[i], static_cast<EventKind>(kind[i]), static_cast<std::int32_t>(partner[i]),
                 static_cast<std::uint32_t>(partner_counter[i])};
  }
  return events;
}

}  // namespace

void writeEngineState(h5::File& file, const std::string& group, const EngineState& s) {
  file.createGroup(group);
  const std::string p = group + "/particles/";
  file.createGroup(group + "/particles");
  const auto& ps = s.particles;
  writeColumn<double>(file, p + "x", ps, [](const ParticleState& q) { return q.x; });
  writeColumn<double>(file, p + "z", ps, [](const ParticleState& q) { return q.z; });
  writeColumn<double>(file, p + "vx", ps, [](const ParticleState& q) { return q.vx; });
  writeColumn<double>(file, p + "vz", ps, [](const ParticleState& q) { return q.vz; });
  writeColumn<double>(file, p + "t", ps, [](const ParticleState& q) { return q.t; });
  writeColumn<double>(file, p + "ride_offset", ps,
                      [](const ParticleState& q) { return q.ride_offset; });
  writeColumn<std::uint64_t>(file, p + "counter", ps,
                             [](const ParticleState& q) { return q.counter; });
  writeColumn<std::uint64_t>(file, p + "motion", ps,
                             [](const ParticleState& q) { return static_cast<int>(q.motion); });
  writeColumn<double>(file, p + "omega", ps, [](const ParticleState& q) { return q.omega; });
  writeColumn<double>(file, p + "last_collision", ps,
                      [](const ParticleState& q) { return q.last_collision; });
  writeColumn<double>(file, p + "burst_start", ps,
                      [](const ParticleState& q) { return q.burst_start; });
  writeColumn<std::uint64_t>(file, p + "burst", ps, [](const ParticleState& q) { return q.burst; });
  writeColumn<std::uint64_t>(file, p + "rattle", ps,
                             [](const ParticleState& q) { return q.rattle; });
  writeColumn<std::uint64_t>(file, p + "enduring", ps,
                             [](const ParticleState& q) { return q.enduring; });

  writeEvents(file, group + "/events", s.events);
  writeEvents(file, group + "/pair_events", s.pair_events);

  file.writeDataset(group + "/queue_keys", s.queue.keys, {s.queue.keys.size()});
  file.writeDataset(group + "/queue_ids", toInt64(s.queue.ids), {s.queue.ids.size()});
  file.writeDataset(group + "/cell_head", toInt64(s.cells.head), {s.cells.head.size()});
  file.writeDataset(group + "/cell_next", toInt64(s.cells.next), {s.cells.next.size()});
  file.writeDataset(group + "/cell_prev", toInt64(s.cells.prev), {s.cells.prev.size()});
  file.writeDataset(group + "/cell_of", toInt64(s.cells.cell), {s.cells.cell.size()});

  file.writeDataset(group + "/observables_real", realsOf(s.observables), {kObservableReals});
  file.writeDataset(group + "/observables_count", countsOf(s.observables), {kObservableCounts});
  file.writeAttribute(group, "now", s.now);
  file.writeAttribute(group, "records", static_cast<std::uint64_t>(s.records));
  file.writeAttribute(group, "next_record", s.next_record);
  file.writeAttribute(group, "virial", s.virial);
  file.writeAttribute(group, "virial_since", s.virial_since);
  file.writeAttribute(group, "bottom_impulse", s.bottom_impulse);
  file.writeAttribute(group, "sleeps", s.sleeps);
  file.writeAttribute(group, "sleep_alarm_time", s.sleep_alarm_time);
}

EngineState readEngineState(const h5::File& file, const std::string& group) {
  EngineState s;
  const std::string p = group + "/particles/";
  const std::size_t n = file.shape(p + "x").at(0);
  const auto x = readColumn<double>(file, p + "x", n), z = readColumn<double>(file, p + "z", n),
             vx = readColumn<double>(file, p + "vx", n), vz = readColumn<double>(file, p + "vz", n),
             t = readColumn<double>(file, p + "t", n),
             ride = readColumn<double>(file, p + "ride_offset", n),
             omega = readColumn<double>(file, p + "omega", n),
             last = readColumn<double>(file, p + "last_collision", n),
             burst_start = readColumn<double>(file, p + "burst_start", n);
  const auto counter = readColumn<std::uint64_t>(file, p + "counter", n),
             motion = readColumn<std::uint64_t>(file, p + "motion", n),
             burst = readColumn<std::uint64_t>(file, p + "burst", n);
  s.particles.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    ParticleState& q = s.particles[i];
    if (motion[i] > static_cast<std::uint64_t>(Motion::RideLid))
      throw h5::H5Error(file.name() + ": " + p + "motion holds " + std::to_string(motion[i]) +
                        ", valid are 0-2");
    q.x = x[i];
    q.z = z[i];
    q.vx = vx[i];
    q.vz = vz[i];
    q.t = t[i];
    q.ride_offset = ride[i];
    q.counter = static_cast<std::uint32_t>(counter[i]);
    q.motion = static_cast<Motion>(motion[i]);
    q.omega = omega[i];
    q.last_collision = last[i];
    q.burst_start = burst_start[i];
    q.burst = static_cast<std::uint32_t>(burst[i]);
  }
  // Absent in states saved before the sleep rule (docs/physics.md, "Resting contacts").
  if (file.exists(p + "rattle")) {
    const auto rattle = readColumn<std::uint64_t>(file, p + "rattle", n);
    for (std::size_t i = 0; i < n; ++i)
      s.particles[i].rattle = static_cast<std::uint16_t>(rattle[i]);
  }
  // Absent in states saved before the sleep rule's alarm.
  if (file.exists(p + "enduring")) {
    const auto enduring = readColumn<std::uint64_t>(file, p + "enduring", n);
    for (std::size_t i = 0; i < n; ++i)
      s.particles[i].enduring = static_cast<std::uint32_t>(enduring[i]);
  }

  s.events = readEvents(file, group + "/events", n);
  // Absent in states saved before the engine kept each particle's earliest pair event.
  if (file.exists(group + "/pair_events"))
    s.pair_events = readEvents(file, group + "/pair_events", n);

  s.queue.keys = readColumn<double>(file, group + "/queue_keys", n);
  s.queue.ids = toInts(readColumn<std::int64_t>(file, group + "/queue_ids", n));
  s.cells.head = toInts(file.readDataset<std::int64_t>(group + "/cell_head"));
  s.cells.next = toInts(readColumn<std::int64_t>(file, group + "/cell_next", n));
  s.cells.prev = toInts(readColumn<std::int64_t>(file, group + "/cell_prev", n));
  s.cells.cell = toInts(readColumn<std::int64_t>(file, group + "/cell_of", n));
  const auto reals = file.readDataset<double>(group + "/observables_real", {kObservableReals});
  const auto counts =
      file.readDataset<std::uint64_t>(group + "/observables_count", {kObservableCounts});
  s.observables = observablesFrom(reals.data(), counts.data());
  s.now = file.readAttribute<double>(group, "now");
  s.records = file.readAttribute<std::uint64_t>(group, "records");
  s.next_record = file.readAttribute<double>(group, "next_record");
  s.virial = file.readAttribute<double>(group, "virial");
  s.virial_since = file.readAttribute<double>(group, "virial_since");
  if (file.hasAttribute(group, "sleeps")) {
    s.bottom_impulse = file.readAttribute<double>(group, "bottom_impulse");
    s.sleeps = file.readAttribute<std::uint64_t>(group, "sleeps");
  }
  if (file.hasAttribute(group, "sleep_alarm_time"))
    s.sleep_alarm_time = file.readAttribute<double>(group, "sleep_alarm_time");
  return s;
}

void writeSnapshots(h5::File& file, const std::string& group,
                    const std::vector<Snapshot>& snapshots) {
  file.createGroup(group);
  const std::size_t count = snapshots.size();
  const std::size_t n = count ? snapshots[0].x.size() : 0;
  std::vector<double> x, z, vx, vz, omega, time, plate, reals;
  std::vector<std::uint64_t> step, counts;
  for (const Snapshot& s : snapshots) {
    if (s.x.size() != n || s.z.size() != n || s.vx.size() != n || s.vz.size() != n ||
        s.omega.size() != n)
      throw h5::H5Error(file.name() + ": " + group + ": snapshots of different particle counts");
    x.insert(x.end(), s.x.begin(), s.x.end());
    z.insert(z.end(), s.z.begin(), s.z.end());
    vx.insert(vx.end(), s.vx.begin(), s.vx.end());
    vz.insert(vz.end(), s.vz.begin(), s.vz.end());
    omega.insert(omega.end(), s.omega.begin(), s.omega.end());
    step.push_back(s.step);
    time.push_back(s.time);
    plate.push_back(s.plate_height);
    const auto r = realsOf(s.obs);
    const auto c = countsOf(s.obs);
    reals.insert(reals.end(), r.begin(), r.end());
    counts.insert(counts.end(), c.begin(), c.end());
  }
  file.writeDataset(group + "/x", x, {count, n});
  file.writeDataset(group + "/z", z, {count, n});
  file.writeDataset(group + "/vx", vx, {count, n});
  file.writeDataset(group + "/vz", vz, {count, n});
  file.writeDataset(group + "/omega", omega, {count, n});
  file.writeDataset(group + "/step", step, {count});
  file.writeDataset(group + "/time", time, {count});
  file.writeDataset(group + "/plate_height", plate, {count});
  file.writeDataset(group + "/observables_real", reals, {count, kObservableReals});
  file.writeDataset(group + "/observables_count", counts, {count, kObservableCounts});
}

std::vector<Snapshot> readSnapshots(const h5::File& file, const std::string& group) {
  const h5::Shape shape = file.shape(group + "/x");
  if (shape.size() != 2) throw h5::H5Error(file.name() + ": " + group + "/x is not 2D");
  const std::size_t count = shape[0], n = shape[1];
  const auto x = file.readDataset<double>(group + "/x", {count, n}),
             z = file.readDataset<double>(group + "/z", {count, n}),
             vx = file.readDataset<double>(group + "/vx", {count, n}),
             vz = file.readDataset<double>(group + "/vz", {count, n}),
             omega = file.readDataset<double>(group + "/omega", {count, n}),
             time = file.readDataset<double>(group + "/time", {count}),
             plate = file.readDataset<double>(group + "/plate_height", {count}),
             reals =
                 file.readDataset<double>(group + "/observables_real", {count, kObservableReals});
  const auto step = file.readDataset<std::uint64_t>(group + "/step", {count}),
             counts = file.readDataset<std::uint64_t>(group + "/observables_count",
                                                      {count, kObservableCounts});
  std::vector<Snapshot> out(count);
  for (std::size_t k = 0; k < count; ++k) {
    Snapshot& s = out[k];
    const auto from = static_cast<std::ptrdiff_t>(k * n),
               to = static_cast<std::ptrdiff_t>((k + 1) * n);
    s.x.assign(x.begin() + from, x.begin() + to);
    s.z.assign(z.begin() + from, z.begin() + to);
    s.vx.assign(vx.begin() + from, vx.begin() + to);
    s.vz.assign(vz.begin() + from, vz.begin() + to);
    s.omega.assign(omega.begin() + from, omega.begin() + to);
    s.step = step[k];
    s.time = time[k];
    s.plate_height = plate[k];
    s.obs = observablesFrom(&reals[k * kObservableReals], &counts[k * kObservableCounts]);
  }
  return out;
}

}  // namespace granwave
