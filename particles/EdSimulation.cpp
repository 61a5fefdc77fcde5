#include "particles/EdSimulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "particles/EventLoopStall.hpp"

namespace granwave {

EdSimulation::EdSimulation(const EngineConfig& config, const InitialCondition& init)
    : cfg_(config), rotation_(tracksSpin(config)) {
  const int n = init.size();
  setUp(n);
  const double d = cfg_.diameter;
  p_.resize(n);
  ev_.resize(n);
  pair_ev_.resize(n);
  queue_.reset(n);
  const double tol = 1e-9 * d;
  for (int i = 0; i < n; ++i) {
    ParticleState& s = p_[i];
    s.x = init.x[i];
    s.z = init.z[i];
    s.vx = init.vx[i];
    s.vz = init.vz[i];
    s.omega = rotation_ && !init.omega.empty() ? init.omega[i] : 0.0;
    if (!std::isfinite(s.x) || !std::isfinite(s.z) || !std::isfinite(s.vx) || !std::isfinite(s.vz))
      throw std::invalid_argument(fmt::format("particle {} has a non-finite initial state", i));
    if (cfg_.periodic_x) {
      s.x -= cfg_.width * std::floor(s.x / cfg_.width);
    } else if (s.x < 0.5 * d - tol || s.x > cfg_.width - 0.5 * d + tol) {
      throw std::invalid_argument(
          fmt::format("particle {} at x = {:.6g} m lies outside the side walls", i, s.x));
    }
    if (cfg_.periodic_z) {
      s.z -= cfg_.height * std::floor(s.z / cfg_.height);
    } else {
      const double zb = cfg_.plate.height(0.0);
      if (s.z < zb + 0.5 * d - tol || s.z > zb + cfg_.height - 0.5 * d + tol)
        throw std::invalid_argument(
            fmt::format("particle {} at z = {:.6g} m lies outside bottom and lid", i, s.z));
    }
    cells_.insert(i, cells_.locate(s.x, s.z));
  }
  for (int i = 0; i < n; ++i) {
    const int c = cells_.cellOf(i);
    CellGrid::Neighbour nb[9];
    const int m = cells_.neighbours(c, nb);
    for (int k = 0; k < m; ++k) {
      for (const int j : cells_.members(nb[k].cell)) {
        if (j <= i) continue;
        const double dx = p_[i].x - p_[j].x - nb[k].shift_x;
        const double dz = p_[i].z - p_[j].z - nb[k].shift_z;
        if (dx * dx + dz * dz < d * d * (1 - 1e-9))
          throw std::invalid_argument(fmt::format(
              "particles {} and {} overlap in the initial state (distance {:.6g} m < d = {:.6g} m)",
              i, j, std::sqrt(dx * dx + dz * dz), d));
      }
    }
  }
  for (int i = 0; i < n; ++i) predict(i);
}

EdSimulation::EdSimulation(const EngineConfig& config, const EngineState& saved)
    : cfg_(config), rotation_(tracksSpin(config)) {
  const int n = static_cast<int>(saved.particles.size());
  setUp(n);
  if (saved.events.size() != saved.particles.size())
    throw std::invalid_argument(
        fmt::format("saved engine state: {} events for {} particles", saved.events.size(), n));
  queue_.restore(saved.queue);
  if (queue_.size() != n)
    throw std::invalid_argument(fmt::format(
        "saved engine state: the event queue holds {} particles, the state {}", queue_.size(), n));
  for (int i = 0; i < n; ++i)
    if (!(queue_.time(i) == saved.events[i].time))
      throw std::invalid_argument(
          fmt::format("saved engine state: particle {} is queued at t = {} s, its event at {} s", i,
                      queue_.time(i), saved.events[i].time));
  cells_.restore(saved.cells);
  if (!(saved.now >= 0) || !(saved.next_record >= saved.now))
    throw std::invalid_argument(
        fmt::format("saved engine state: clock at {} s with the next record at {} s", saved.now,
                    saved.next_record));
  p_ = saved.particles;
  ev_ = saved.events;
  if (saved.pair_events.empty()) {
    pair_ev_.assign(n, Event{-std::numeric_limits<double>::infinity()});
  } else if (static_cast<int>(saved.pair_events.size()) == n) {
    pair_ev_ = saved.pair_events;
  } else {
    throw std::invalid_argument(fmt::format("saved engine state: {} pair events for {} particles",
                                            saved.pair_events.size(), n));
  }
  obs_ = saved.observables;
  now_ = saved.now;
  records_ = saved.records;
  next_record_ = saved.next_record;
  virial_ = saved.virial;
  virial_since_ = saved.virial_since;
  bottom_impulse_ = saved.bottom_impulse;
  sleeps_ = saved.sleeps;
  sleep_alarm_time_ = saved.sleep_alarm_time;
}

EngineState EdSimulation::state() const {
  EngineState s;
  s.particles = p_;
  s.events = ev_;
  s.pair_events = pair_ev_;
  s.queue = queue_.layout();
  s.cells = cells_.lists();
  s.observables = obs_;
  s.now = now_;
  s.records = records_;
  s.next_record = next_record_;
  s.virial = virial_;
  s.virial_since = virial_since_;
  s.bottom_impulse = bottom_impulse_;
  s.sleeps = sleeps_;
  s.sleep_alarm_time = sleep_alarm_time_;
  return s;
}

// Checks the config, builds the (empty) cell grid and the curvature bounds for n particles.
void EdSimulation::setUp(int n) {
  const double d = cfg_.diameter;
  if (n < 1) throw std::invalid_argument("a simulation needs at least one particle");
  if (cfg_.periodic_z && cfg_.plate.amplitude > 0)
    throw std::invalid_argument(
        "container.periodic_z needs an undriven scene (drive.frequency = 0)");

  // Lab-frame grid covering every height a centre can reach: [-A, L_z + A] with walls,
  // [0, L_z) periodic (docs/fields.md uses the same extent).
  CellGeometry g;
  g.periodic_x = cfg_.periodic_x;
  g.periodic_z = cfg_.periodic_z;
  g.nx = cellsAlong(cfg_.width, d);
  g.wx = cfg_.width / g.nx;
  const double A = cfg_.plate.amplitude;
  const double span = cfg_.periodic_z ? cfg_.height : cfg_.height + 2 * A;
  g.nz = cellsAlong(span, d);
  g.wz = span / g.nz;
  g.z0 = cfg_.periodic_z ? 0.0 : -A;
  if ((g.periodic_x && g.nx < 3) || (g.periodic_z && g.nz < 3))
    throw std::invalid_argument("a periodic direction must be at least 3 particle diameters long");
  cells_ = CellGrid(g, n);
  // Without bottom and lid nothing rides a wall: every pair time is then exact for all
  // future times, so a prediction may be carried over a cell crossing (pair_ev_).
  incremental_crossings_ = cfg_.periodic_z;

  const double aw2 = cfg_.plate.maxAcceleration();
  bottom_curvature_ = cfg_.gravity + aw2;
  lid_curvature_ = std::max(0.0, aw2 - cfg_.gravity);
  pair_curvature_ = cfg_.gravity + aw2;
}

void EdSimulation::advance(int i, double t) {
  ParticleState& s = p_[i];
  const double dt = t - s.t;
  if (s.motion == Motion::Ballistic) {
    s.x += s.vx * dt;
    s.z += (s.vz - 0.5 * cfg_.gravity * dt) * dt;
    s.vz -= cfg_.gravity * dt;
  } else {
    // The wall carries the particle: its energy changes by the wall's work.
    const double before = particleEnergy(s);
    // The bottom's support over dt: m (g dt + change of the plate's velocity).
    if (s.motion == Motion::RideBottom)
      bottom_impulse_ += cfg_.mass * (cfg_.gravity * dt + plateAt(t).velocity - s.vz);
    s.x += s.vx * dt;
    s.z = plateAt(t).height + s.ride_offset;
    s.vz = plateAt(t).velocity;
    obs_.wall_work += particleEnergy(s) - before;
  }
  s.t = t;
}

ParticleState EdSimulation::extrapolated(int i, double t) const {
  ParticleState s = p_[i];
  const double dt = t - s.t;
  s.x += s.vx * dt;
  if (s.motion == Motion::Ballistic) {
    s.z += (s.vz - 0.5 * cfg_.gravity * dt) * dt;
    s.vz -= cfg_.gravity * dt;
  } else {
    s.z = plateAt(t).height + s.ride_offset;
    s.vz = plateAt(t).velocity;
  }
  s.t = t;
  return s;
}

double EdSimulation::particleEnergy(const ParticleState& s) const {
  const double m = cfg_.mass;
  const double inertia = m * cfg_.diameter * cfg_.diameter / 10.0;
  return 0.5 * m * (s.vx * s.vx + s.vz * s.vz) + 0.5 * inertia * s.omega * s.omega +
         m * cfg_.gravity * s.z;
}

bool EdSimulation::wallPushes(WallId wall, double t) const {
  // A wall holds a resting particle while its acceleration, relative to free fall, points
  // into the container: bottom while z_b'' > -g, lid while z_b'' < -g.
  // At the switching instant itself (a = -g up to round-off, e.g. at a take-off event) the
  // sign of the jerk says which side the next instant is on.
  if (wall != kBottom && wall != kLid) return false;
  const double excess = plateAt(t).acceleration + cfg_.gravity;  // > 0: bottom pushes
  const double scale = cfg_.gravity + cfg_.plate.maxAcceleration();
  double side = excess;
  if (std::abs(excess) <= 1e-9 * scale) side = plateAt(t).jerk;
  return wall == kBottom ? side > 0.0 : side < 0.0;
}

Vec2 EdSimulation::position(int i) const {
  const ParticleState s = extrapolated(i, now_);
  return {s.x, s.z};
}

double EdSimulation::bottomImpulse() const {
  double impulse = bottom_impulse_;
  for (const ParticleState& s : p_)
    if (s.motion == Motion::RideBottom)
      impulse += cfg_.mass * (cfg_.gravity * (now_ - s.t) + plateAt(now_).velocity - s.vz);
  return impulse;
}

Vec2 EdSimulation::velocity(int i) const {
  const ParticleState s = extrapolated(i, now_);
  return {s.vx, s.vz};
}

Snapshot EdSimulation::snapshot() const {
  Snapshot snap;
  const int n = size();
  snap.time = now_;
  snap.step = records_;
  snap.plate_height = plateAt(now_).height;
  snap.x.resize(n);
  snap.z.resize(n);
  snap.vx.resize(n);
  snap.vz.resize(n);
  snap.omega.resize(n);
  Observables o = obs_;
  const double m = cfg_.mass;
  const double inertia = m * cfg_.diameter * cfg_.diameter / 10.0;
  double zsum = 0, ke = 0, rot = 0;
  for (int i = 0; i < n; ++i) {
    const ParticleState s = extrapolated(i, now_);
    snap.x[i] = s.x;
    snap.z[i] = s.z;
    snap.vx[i] = s.vx;
    snap.vz[i] = s.vz;
    snap.omega[i] = s.omega;
    zsum += s.z;
    ke += 0.5 * m * (s.vx * s.vx + s.vz * s.vz);
    rot += 0.5 * inertia * s.omega * s.omega;
    if (p_[i].motion != Motion::Ballistic) o.wall_work += particleEnergy(s) - particleEnergy(p_[i]);
  }
  o.center_of_mass_height = zsum / n;
  o.kinetic_energy = ke;
  o.rotational_energy = rot;
  o.potential_energy = m * cfg_.gravity * zsum;
  o.pressure = 0;
  if (cfg_.periodic_x && cfg_.periodic_z) {
    // 2D virial theorem for hard disks: P A = E_kin + (1/(2 dt)) sum_coll r_ij . dp_i
    const double dt = now_ - virial_since_;
    o.pressure = (ke + (dt > 0 ? virial_ / (2.0 * dt) : 0.0)) / (cfg_.width * cfg_.height);
  }
  snap.obs = o;
  return snap;
}

void EdSimulation::record() {
  const Snapshot snap = snapshot();
  for (SnapshotObserver* o : observers_) o->observe(snap);
  virial_ = 0;
  virial_since_ = now_;
  ++records_;
  next_record_ = static_cast<double>(records_) * cfg_.record_interval;
}

// Every kPollEvents events the loop looks at the interrupt flag and the event budget: at about
// 10^6 events per second that is every few milliseconds, and the check costs nothing.
constexpr std::uint64_t kPollEvents = 4096;

void EdSimulation::checkEventBudget() const {
  if (cfg_.max_event_rate <= 0) return;
  const double allowed = cfg_.max_event_rate * now_ + cfg_.max_event_rate_grace;
  if (static_cast<double>(obs_.events) > allowed)
    throw EventLoopStall(fmt::format(
        "the run would not finish: {} events by t = {:.6g} s, more than the limit of {:.3g} "
        "events per simulated second (10^4 per particle per d / v, docs/scenes.md)",
        obs_.events, now_, cfg_.max_event_rate));
}

bool EdSimulation::advanceTo(double t, const std::atomic<bool>* interrupt) {
  if (t < now_)
    throw std::invalid_argument(
        fmt::format("advanceTo({:.9g} s) would move the clock back from {:.9g} s", t, now_));
  // A stall: 5e7 events while the clock moves less than the collapse window (1e-3 d over the
  // velocity scale, where a physical run makes a handful of events per particle): a cycle of
  // events at one instant, or a Zeno cascade of ever closer ones, which would otherwise hang
  // the run.
  std::uint64_t stalled = 0;
  double since = now_;
  const double window = cfg_.collapse_window > 0 ? cfg_.collapse_window : 0.0;
  while (queue_.topTime() <= t) {
    now_ = queue_.topTime();
    const int i = queue_.top();
    // The particles likely to come next: their states and events are requested from memory
    // now, so that in a large system the wait overlaps this event's work
    // (docs/performance.md, "Where the large gas waits on memory").
    for (int k = 1; k <= 2; ++k) {
      const int j = queue_.follower(k);
      if (j < 0) break;
      __builtin_prefetch(&p_[j]);
      __builtin_prefetch(&ev_[j]);
    }
    process(i);
    if (++obs_.events % kPollEvents == 0) {
      checkEventBudget();
      if (interrupt && interrupt->load(std::memory_order_relaxed)) return false;
    }
    if (now_ - since <= window) {
      if (++stalled > 50'000'000)
        throw EventLoopStall(fmt::format(
            "event loop stalled: 5e7 events while the clock moved {:.3g} s (less than {:.3g} s) "
            "from t = {:.12g} s",
            now_ - since, window, since));
    } else {
      stalled = 0;
      since = now_;
    }
  }
  now_ = t;
  return true;
}

RunStatus EdSimulation::run(const std::atomic<bool>* interrupt,
                            const std::function<bool()>& pause) {
  RunStatus st;
  const double end = cfg_.duration;
  const double eps = 1e-12 * std::max(end, cfg_.record_interval);
  // Records already in the past (after an advanceTo) are skipped, never extrapolated back.
  while (static_cast<double>(records_) * cfg_.record_interval < now_ - eps) ++records_;
  next_record_ = static_cast<double>(records_) * cfg_.record_interval;
  while (true) {
    const double t_stop = std::min(next_record_, end);
    if (!advanceTo(t_stop, interrupt)) {
      st.interrupted = true;
      st.at_record = false;
      break;
    }
    if (now_ >= next_record_ - eps && next_record_ <= end + eps) {
      now_ = next_record_;
      record();
    }
    if (now_ >= end - eps && next_record_ > end + eps) {
      st.completed = true;
      break;
    }
    if (interrupt && interrupt->load(std::memory_order_relaxed)) {
      st.interrupted = true;
      break;
    }
    // Only here, between a record and the next advance, is the whole state in the saved
    // fields (now_ = the record time, next_record_ set): a checkpoint taken now and a
    // run() called again continue exactly as if no pause had happened.
    if (pause && pause()) {
      st.paused = true;
      break;
    }
  }
  st.time = now_;
  st.events = obs_.events;
  return st;
}

}  // namespace granwave
