#pragma once
// Event-driven (ED) hard-sphere simulation of a quasi-2D vibrated granular layer
// (paper, Methods; as implemented: docs/physics.md).
//
// Particles fly ballistically under gravity between instantaneous events: pair collisions
// (exact quadratic), collisions with the sinusoidally moving bottom and lid (exact first
// root via GapRootFinder), side walls, cell crossings, and take-off of particles riding a
// wall. Each particle keeps one scheduled event in a calendar queue (EventQueue.hpp);
// events made stale by a partner's collision are dropped lazily by collision counters;
// particles are advanced lazily. Recording extrapolates all particles to the recording time
// without changing the state. Cost per event O(1) on average (the calendar queue; O(log N)
// at worst, for many equal times), memory O(N).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "particles/CellGrid.hpp"
#include "particles/CollisionRule.hpp"
#include "particles/EngineState.hpp"
#include "particles/Event.hpp"
#include "particles/EventQueue.hpp"
#include "particles/PairImpactHistogram.hpp"
#include "particles/ParticleState.hpp"
#include "particles/PlateMotion.hpp"
#include "particles/Restitution.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

struct Scene;

// TC window (paper: "only the first collision of each particle within this time scale is
// inelastic"): Rolling restarts a particle's t_c clock at every collision (Luding & McNamara
// 1998); Anchored starts it at the first collision after the previous window closed, so a
// particle has at most one dissipative collision per t_c.
enum class TcWindowRule { Rolling, Anchored };

// Everything the engine needs, resolved from a Scene (engineConfig) or set by tests.
struct EngineConfig {
  double diameter = 0.002, mass = 1, gravity = 9.81;
  double width = 0.06, height = 0.06;  // container L_x, L_z
  bool periodic_x = false, periodic_z = false;
  PlateMotion plate;
  Restitution restitution = Restitution::constant(1.0);
  TangentialLaw tangential;
  TangentialRule wall_tangential = TangentialRule::Smooth;  // walls (outside the TC time)
  TangentialRule tc_tangential = TangentialRule::Smooth;    // collisions the TC model makes elastic
  TcWindowRule tc_window = TcWindowRule::Rolling;
  double tc = 0;       // s; 0 = TC model off
  bool sleep = false;  // put particles at rest on the bottom to sleep (RestingContact.cpp)
  // A particle with this many enduring collisions in a row (each within t_c of the previous
  // one) switches the rule on for the rest of the run if it is off; with it on, its contact
  // group collides perfectly inelastically (RestingContact.cpp). 0 = neither.
  std::uint32_t sleep_alarm = 0;
  double rest_velocity = 1e-6;
  double duration = 1;  // s
  double record_interval = 0.01;
  // Collapse detection: more than `collapse_collisions` collisions of one particle within
  // `collapse_window` seconds.
  std::uint32_t collapse_collisions = 2000;
  double collapse_window = 1e-6;
  // A run that can never finish: more than max_event_rate x t + max_event_rate_grace events by
  // simulated time t stops it (EventLoopStall). 0 = no limit. engineConfig sets 10^4 events
  // per particle per d / v (docs/scenes.md, "Why these ranges").
  double max_event_rate = 0;  // events per simulated second, whole system
  double max_event_rate_grace = 0;
};

// contact.sleep = "auto" or "on": the enduring collisions in a row that switch the sleep rule
// on, or end a rattle it did not (EngineConfig::sleep_alarm; docs/physics.md, "Resting
// contacts", item 7).
inline constexpr std::uint32_t kAutoSleepAlarm = 500;

EngineConfig engineConfig(const Scene& scene);

// Whether any contact of this config can give a tangential impulse (so spins are tracked).
bool tracksSpin(const EngineConfig& config);

struct RunStatus {
  bool completed = false;    // reached the duration
  bool interrupted = false;  // stopped by the interrupt flag
  bool paused = false;       // stopped because the pause predicate asked (a checkpoint)
  // false when the interrupt came between two records: the state is then not at a record and
  // must not be checkpointed (a later run() would not continue exactly).
  bool at_record = true;
  double time = 0;
  std::uint64_t events = 0;
};

class EdSimulation {
 public:
  EdSimulation(const EngineConfig& config, const InitialCondition& initial);
  // Continues a run from a state saved by state() under the same config (checkpoints).
  // std::invalid_argument if the state does not fit the config.
  EdSimulation(const EngineConfig& config, const EngineState& saved);

  void addObserver(SnapshotObserver* observer) { observers_.push_back(observer); }
  // Sees every pair collision's pre-collision normal speed (PairImpactHistogram.hpp); one
  // observer, or none (nullptr).
  void setPairImpactObserver(PairImpactObserver* observer) { impact_observer_ = observer; }
  // Runs to config.duration, recording every record_interval (t = 0 included).
  // Stops early when *interrupt is set (polled every few thousand events, so within
  // milliseconds even inside a long record), or after a record when pause() returns true (it
  // is asked once per record); after a pause a later run() continues exactly where this one
  // stopped.
  RunStatus run(const std::atomic<bool>* interrupt = nullptr,
                const std::function<bool()>& pause = {});
  // Processes events up to time t >= now() (no recording); for tests and benchmarks.
  // std::invalid_argument if t < now(). Returns false if it stopped early at *interrupt
  // (then now() < t).
  bool advanceTo(double t, const std::atomic<bool>* interrupt = nullptr);

  Snapshot snapshot() const;  // extrapolated to now()
  EngineState state() const;  // everything a restart needs, as stored
  double now() const { return now_; }
  const Observables& counters() const { return obs_; }
  const EngineConfig& config() const { return cfg_; }
  int size() const { return static_cast<int>(p_.size()); }
  // Current lab-frame position of particle i (extrapolated).
  Vec2 position(int i) const;
  Vec2 velocity(int i) const;
  // Vertical impulse the bottom has given the particles since t = 0 (N s): impacts, the
  // velocity absorbed when a particle comes to rest on it or on its riders, and the
  // continuous support of everything it carries, the integral of m (g + z_b'') over the time
  // each particle rides it (to now()). Over a window, its increase divided by the window's
  // length is the plate's time-averaged force; at rest it equals N m g.
  double bottomImpulse() const;
  // Particles put to sleep so far (docs/physics.md, "Resting contacts", item 7).
  std::uint64_t sleeps() const { return sleeps_; }
  // When the sleep rule's alarm switched it on (EngineConfig::sleep_alarm), s; negative if it
  // did not.
  double sleepAlarmTime() const { return sleep_alarm_time_; }

 private:
  void setUp(int particles);
  // prediction (EventPrediction.cpp)
  void predict(int i);
  // Schedules i's earliest event from its earliest pair event and its own crossings and walls
  // (the crossing given if already predicted).
  void schedule(int i, const ParticleState& s, const Event& pair);
  void schedule(int i, const ParticleState& s, const Event& pair, const Event& crossing);
  void predictCrossing(int i, const ParticleState& s, Event& best) const;
  // First time >= now_ at which a rider's height minus its offset, z_b(t), passes u rising
  // (or falling); +inf if never.
  double riderCrossingTime(double u, bool rising) const;
  void predictWalls(int i, const ParticleState& s, Event& best, double horizon) const;
  void predictBottomAndLid(const ParticleState& s, Event& best, double horizon) const;
  // Pairs of i with the particles of the m stencil cells nb (earliest into best).
  void predictPairWith(int i, const ParticleState& s, double speed_i, int j,
                       const CellGrid::Neighbour& nb, Event& best) const;
  void predictPairs(int i, const ParticleState& s, const CellGrid::Neighbour* nb, int m,
                    Event& best) const;
  // execution (EventExecution.cpp)
  void process(int i);
  void doPair(int i, int j, Vec2 image_shift);
  void doRiderPair(int i, int j, double rx);
  void doWall(int i, WallId wall);
  void doCross(int i, CrossDirection dir);
  void doTakeOff(int i);
  void startRiding(int i, WallId wall);
  // Approach speed below which a pair's approach is round-off (see PairCollisionTime).
  double approachTolerance(double speed_a, double speed_b) const;
  // Acceleration (m/s^2) with which a rider presses a flyer along n (rider -> flyer); <= 0
  // when it does not (then there is no resting contact between them).
  double riderPress(const ParticleState& rider, const ParticleState& other, Vec2 n) const;
  bool riderPresses(const ParticleState& rider, const ParticleState& other, Vec2 n) const {
    return riderPress(rider, other, n) > 0.0;
  }
  // Largest separation speed of a resting contact pressed with acceleration `press` (normal
  // component, m/s^2): rest_velocity, or with the TC model on the speed at which the particle
  // would come back within t_c, press t_c / 2 (docs/physics.md, "Resting contacts").
  double restSpeed(double press) const {
    return std::max(cfg_.rest_velocity, 0.5 * press * cfg_.tc);
  }
  // The pressing acceleration of a wall (bottom or lid) at now_ (<= 0: it does not push).
  double wallPress(WallId wall) const {
    const double excess = plateAt(now_).acceleration + cfg_.gravity;
    return wall == kBottom ? excess : wall == kLid ? -excess : 0.0;
  }
  bool attachToRider(int i, ParticleState& rider, Vec2 r_rider_to_i);
  // Without friction a flyer moving horizontally into its rider (rx = flyer - rider
  // horizontally, dvx = flyer - rider velocity) cannot rest on it: attachToRider refuses, so
  // prediction must not schedule that rest either (it would repeat at one instant forever).
  bool slidesIntoSupport(double rx, double dvx) const {
    return cfg_.tangential.friction <= 0.0 && rx * dvx < 0.0;
  }
  void settleRiders(int i, int j, Vec2 n, Vec2 r, double press, double separation);
  bool pinched(int i, Vec2 away, Motion rigid, int exclude) const;
  void noteCollision(int i, int partner);
  // Books a restitution-law pair impact at normal speed v_n (Observables::pair_impact_*).
  void bookImpact(double v_n, double e_n) {
    const double impact = 0.25 * cfg_.mass * v_n * v_n;
    obs_.pair_impact_energy += impact;
    obs_.pair_impact_loss += impact * (1.0 - e_n * e_n);
  }
  bool tcElastic(int i, int j) const;
  // Sleep rule (RestingContact.cpp; docs/physics.md, "Resting contacts", item 7): after
  // kSleepStreak consecutive enduring collisions (each within t_c of the previous one, a
  // flyer's slower than sleepSpeed()), a particle held by the bottom is carried by it with
  // no motion of its own; one not held yet but jammed sideways stops moving relative to the
  // flyers connected to it (moveTogether).
  // 16: the paper's dry scene (Gamma = 4) never reaches it (8 does), and the cost of a layer
  // settling after each landing grows in proportion to it.
  static constexpr std::uint16_t kSleepStreak = 16;
  // A partner is below k when the contact normal (partner -> k) points up by more than 30
  // degrees from the horizontal; particles closer than kContactGap d touch.
  static constexpr double kBelow = 0.5, kContactGap = 1e-4;
  // Slower hits than the speed of a fall through d / 2 are resting contacts, not impacts.
  double sleepSpeed() const { return std::sqrt(cfg_.gravity * cfg_.diameter); }
  // Before noteCollision (it reads the previous collision time); v_n is the normal
  // approach speed.
  void noteRattle(int k, double v_n);
  // k's contacts (closer than kContactGap d): the bottom, or a carried particle from below
  // (bottom); a flying one from below; carried ones or side walls on either side (held_*);
  // anything level with it on either side (left, right).
  struct Contacts {
    bool bottom = false, flyer_below = false;
    bool held_left = false, held_right = false, left = false, right = false;
  };
  Contacts contactsOf(int k) const;
  void moveTogether(int k);
  void sleepIfAtRest(int k);
  // The rule is on from the start (EngineConfig::sleep) or since its alarm.
  bool sleepOn() const { return cfg_.sleep || sleep_alarm_time_ >= 0.0; }
  // Asleep: carried by the bottom with no motion of its own (fallAsleep). Only with the rule
  // on: a rider that merely has no horizontal motion or spin is not asleep.
  bool asleep(const ParticleState& s) const {
    return sleepOn() && s.motion == Motion::RideBottom && s.vx == 0.0 && s.omega == 0.0;
  }
  // Flyer f hits carried particle r slowly; n from r to f, press: riderPress of r on f.
  void bounceOffCarried(int f, int r, Vec2 n, double v_n, double press);
  void fallAsleep(int k);
  // A rider that left the bottom no longer carries the riders resting on it: they, and the
  // ones resting on them, fly again.
  void wakeRestingOn(int k);
  void bookBottomImpulse(const ParticleState& s, double dvz) {
    if (s.motion == Motion::RideBottom) bottom_impulse_ += cfg_.mass * dvz;
  }
  void checkEventBudget() const;
  // state
  void advance(int i, double t);
  ParticleState extrapolated(int i, double t) const;
  double particleEnergy(const ParticleState& s) const;
  bool wallPushes(WallId wall, double t) const;
  // The plate's state at t, remembered for the last t asked (most calls are at now_: each
  // event's predictions and collision rules ask several times, and sin/cos are costly).
  const PlateState& plateAt(double t) const {
    if (!(plate_time_ == t)) {
      plate_ = cfg_.plate.state(t);
      plate_time_ = t;
    }
    return plate_;
  }
  Vec2 imageShiftTo(int i, int j) const;
  void record();

  EngineConfig cfg_;
  std::vector<ParticleState> p_;
  std::vector<Event> ev_;
  // Each particle's earliest pair event at its last prediction (time -inf: not known). A cell
  // crossing leaves the trajectory unchanged, so when every pair time is exact (no particle
  // can ride a wall) it needs to test only the newly adjacent cells against this (DynamO's
  // approach; docs/ARCHITECTURE.md, "Event calendar"). Where particles can ride a wall, the
  // pair search stops at the particle's next crossing, and this holds the earliest pair event
  // before it (an event of kind None at the crossing's time if there is none).
  std::vector<Event> pair_ev_;
  bool incremental_crossings_ = false;
  EventQueue queue_;
  CellGrid cells_;
  std::vector<SnapshotObserver*> observers_;
  PairImpactObserver* impact_observer_ = nullptr;
  Observables obs_;
  double now_ = 0;
  double bottom_curvature_ = 0, lid_curvature_ = 0, pair_curvature_ = 0;
  std::uint64_t records_ = 0;
  double next_record_ = 0;
  double virial_ = 0;  // sum of r_ij . dp_i since the last record (pressure)
  double virial_since_ = 0;
  double bottom_impulse_ = 0;  // N s, to the particles' own times (bottomImpulse)
  std::uint64_t sleeps_ = 0;
  double sleep_alarm_time_ = -1.0;  // s; negative: the alarm has not switched the rule on
  std::vector<char> in_group_;      // moveTogether's scratch: members of the group
  bool rotation_ = false;
  mutable PlateState plate_;  // plateAt's memory
  mutable double plate_time_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace granwave
