// Execution ("what"): carry out the due event of a particle and re-predict whoever's
// trajectory changed. Partners of stale pair events are re-predicted lazily.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "particles/EdSimulation.hpp"
#include "particles/InelasticCollapse.hpp"
#include "particles/PairCollisionTime.hpp"

namespace granwave {

void EdSimulation::process(int i) {
  const Event e = ev_[i];
  switch (e.kind) {
    case EventKind::Pair:
      if (p_[e.partner].counter != e.partner_counter) {
        predict(i);  // the partner has collided since: stale
      } else {
        doPair(i, e.partner, imageShiftTo(i, e.partner));
      }
      return;
    case EventKind::Wall:
      doWall(i, static_cast<WallId>(e.partner));
      return;
    case EventKind::CellCross:
      doCross(i, static_cast<CrossDirection>(e.partner));
      return;
    case EventKind::TakeOff:
      doTakeOff(i);
      return;
    case EventKind::None:
      queue_.update(i, std::numeric_limits<double>::infinity());
      return;
  }
}

Vec2 EdSimulation::imageShiftTo(int i, int j) const {
  // Shift that brings j's position to the image nearest to i, from their cells.
  const CellGeometry& g = cells_.geometry();
  const int ci = cells_.cellOf(i), cj = cells_.cellOf(j);
  Vec2 shift;
  if (g.periodic_x) {
    const int d = cells_.cx(cj) - cells_.cx(ci);
    if (d > 1) shift.x = -g.lx();
    if (d < -1) shift.x = g.lx();
  }
  if (g.periodic_z) {
    const int d = cells_.cz(cj) - cells_.cz(ci);
    if (d > 1) shift.z = -g.lz();
    if (d < -1) shift.z = g.lz();
  }
  return shift;
}

bool EdSimulation::tcElastic(int i, int j) const {
  // TC model (Luding & McNamara 1998): a collision is elastic if a partner's TC window
  // (opened at its last collision, or its first one in the window when anchored) is open.
  // A wall (j < 0) is a partner with no memory.
  if (cfg_.tc <= 0.0) return false;
  if (now_ - p_[i].last_collision < cfg_.tc) return true;
  return j >= 0 && now_ - p_[j].last_collision < cfg_.tc;
}

void EdSimulation::noteCollision(int i, int partner) {
  ParticleState& s = p_[i];
  // last_collision opens the particle's TC window: at every collision (rolling), or only at
  // the first one after the window closed (anchored).
  if (cfg_.tc_window == TcWindowRule::Rolling || !(now_ - s.last_collision < cfg_.tc))
    s.last_collision = now_;
  ++s.counter;
  if (now_ - s.burst_start > cfg_.collapse_window) {
    s.burst_start = now_;
    s.burst = 0;
  }
  if (++s.burst > cfg_.collapse_collisions) {
    const std::string with = partner >= 0 ? fmt::format("particle {}", partner) : "a wall";
    throw InelasticCollapse(
        fmt::format("inelastic collapse at t = {:.9f} s: particle {} collided {} times within "
                    "{:.3g} s (last with {}){}",
                    now_, i, s.burst, cfg_.collapse_window, with,
                    cfg_.tc > 0
                        ? "; the TC model is on, so these collisions were elastic: a contact the "
                          "engine does not resolve (docs/physics.md, \"Inelastic "
                          "collapse\"); please report the scene and seed"
                        : "; switch the TC model on (contact.tc = \"auto\")"),
        now_, i, partner);
  }
}

double EdSimulation::approachTolerance(double speed_a, double speed_b) const {
  return kApproachTolerance * (speed_a + speed_b + std::sqrt(cfg_.gravity * cfg_.diameter));
}

double EdSimulation::riderPress(const ParticleState& rider, const ParticleState& other,
                                Vec2 n_rider_to_other) const {
  // Relative acceleration of a flying particle with respect to a rider is
  // (0, -g - z_b''); the contact is compressed if it points against n (rider -> other).
  if (rider.motion == Motion::Ballistic || other.motion != Motion::Ballistic) return 0.0;
  // At the take-off instant itself g + z_b'' is zero up to round-off: the wall's own rule
  // (the jerk's sign) says whether it still holds its riders; without it a particle could
  // join a layer that has just taken off and ride a whole cycle too long.
  if (!wallPushes(rider.motion == Motion::RideBottom ? kBottom : kLid, now_)) return 0.0;
  return (cfg_.gravity + plateAt(now_).acceleration) * n_rider_to_other.z;
}

void EdSimulation::doRiderPair(int i, int j, double rx) {
  // Two particles carried by the same wall: their vertical separation is fixed, so the
  // contact acts horizontally (the wall takes any vertical impulse). The normal approach
  // speed is the horizontal closing speed times |n_x| = |rx| / d; restoring e times it along
  // n reverses the horizontal relative velocity: a 1D collision in x with e_n(approach).
  // A pair stacked exactly (rx = 0) does not approach at all (riderPairCollisionTime): taking
  // the horizontal speed for the approach there let two riders against a side wall swap
  // their vx forever at one instant (a "collapse" with TC on, wet law, 4 of 72 runs of the
  // stability grid). Riders exist only with walls, so there is no virial to book (pressure is
  // measured in fully periodic boxes).
  ParticleState& a = p_[i];
  ParticleState& b = p_[j];
  const double closing = (rx > 0 ? b.vx - a.vx : a.vx - b.vx) * std::abs(rx) / cfg_.diameter;
  const double tol = approachTolerance(std::abs(a.vx), std::abs(b.vx));
  if (!(closing > tol)) {
    predict(i);
    predict(j);
    return;
  }
  const bool elastic = tcElastic(i, j);
  const double e_n = elastic ? 1.0 : cfg_.restitution(closing);
  const double before = particleEnergy(a) + particleEnergy(b);
  if (!elastic) bookImpact(closing, e_n);
  if (cfg_.tc > 0.0 && closing <= sleepSpeed() && (asleep(a) || asleep(b))) {
    // A slow hit on a sleeper: the bottom holds it (RestingContact.cpp), the other rebounds.
    ParticleState& mover = asleep(a) ? b : a;
    mover.vx = -e_n * mover.vx;
  } else {
    const double mean = 0.5 * (a.vx + b.vx), half = 0.5 * (a.vx - b.vx);
    a.vx = mean - e_n * half;
    b.vx = mean + e_n * half;
  }
  obs_.dissipated_energy += before - particleEnergy(a) - particleEnergy(b);
  ++obs_.collisions.pair;
  if (elastic) ++obs_.collisions.tc_elastic;
  if (impact_observer_) impact_observer_->pairImpact({now_, closing, 0.5 * (a.z + b.z), elastic});
  noteRattle(i, closing);
  noteRattle(j, closing);
  noteCollision(i, j);
  noteCollision(j, i);
  sleepIfAtRest(i);
  sleepIfAtRest(j);
  predict(i);
  predict(j);
}

void EdSimulation::doPair(int i, int j, Vec2 shift) {
  advance(i, now_);
  advance(j, now_);
  ParticleState& a = p_[i];
  ParticleState& b = p_[j];
  const double rx = a.x - b.x - shift.x, rz = a.z - b.z - shift.z;
  if (a.motion == b.motion && a.motion != Motion::Ballistic) {
    doRiderPair(i, j, rx);
    return;
  }
  const double dist = std::sqrt(rx * rx + rz * rz);
  const Vec2 n{rx / dist, rz / dist};
  const Vec2 va{a.vx, a.vz}, vb{b.vx, b.vz};
  const double vn = pairNormalSpeed(n, va, vb);
  // Which partner (if any) is a rider pressing the other: resting contacts attach.
  const bool a_rides = a.motion != Motion::Ballistic, b_rides = b.motion != Motion::Ballistic;
  const double press = a_rides   ? riderPress(a, b, {-n.x, -n.z})
                       : b_rides ? riderPress(b, a, n)
                                 : 0.0;
  const bool pressed = press > 0.0;
  const double tol =
      approachTolerance(std::sqrt(a.vx * a.vx + a.vz * a.vz), std::sqrt(b.vx * b.vx + b.vz * b.vz));
  if (!(vn > tol)) {
    if (pressed && -vn <= restSpeed(press) &&
        (a_rides ? attachToRider(j, a, {-rx, -rz}) : attachToRider(i, b, {rx, rz}))) {
      ++a.counter;
      ++b.counter;
    }
    predict(i);  // otherwise not approaching after all (round-off): nothing happens
    predict(j);
    return;
  }
  if (cfg_.tc > 0.0 && (a_rides ? asleep(a) : b_rides && asleep(b)) && vn <= sleepSpeed()) {
    if (a_rides)
      bounceOffCarried(j, i, {-n.x, -n.z}, vn, press);
    else
      bounceOffCarried(i, j, n, vn, press);
    return;
  }
  const bool elastic = tcElastic(i, j);
  const double e_n = elastic ? 1.0 : cfg_.restitution(vn);
  const double before = particleEnergy(a) + particleEnergy(b);
  if (!elastic) bookImpact(vn, e_n);
  const PairCollisionResult c =
      collidePair(n, va, vb, a.omega, b.omega, cfg_.mass, cfg_.diameter, e_n, cfg_.tangential,
                  elastic ? cfg_.tc_tangential : TangentialRule::Coulomb);
  a.vx = c.v1.x;
  a.vz = c.v1.z;
  b.vx = c.v2.x;
  b.vz = c.v2.z;
  a.omega = c.w1;
  b.omega = c.w2;
  obs_.dissipated_energy += before - particleEnergy(a) - particleEnergy(b);
  virial_ += rx * c.impulse.x + rz * c.impulse.z;
  ++obs_.collisions.pair;
  if (elastic) ++obs_.collisions.tc_elastic;
  if (impact_observer_) impact_observer_->pairImpact({now_, vn, b.z + shift.z + 0.5 * rz, elastic});
  noteRattle(i, vn);
  noteRattle(j, vn);
  noteCollision(i, j);
  noteCollision(j, i);
  if (a_rides || b_rides) settleRiders(i, j, n, {rx, rz}, press, -pairNormalSpeed(n, c.v1, c.v2));
  sleepIfAtRest(i);
  sleepIfAtRest(j);
  predict(i);
  predict(j);
}

void EdSimulation::doWall(int i, WallId wall) {
  advance(i, now_);
  ParticleState& s = p_[i];
  Vec2 n, vw;
  switch (wall) {
    case kBottom:
      n = {0, 1};
      vw = {0, plateAt(now_).velocity};
      break;
    case kLid:
      n = {0, -1};
      vw = {0, plateAt(now_).velocity};
      break;
    case kLeft:
      n = {1, 0};
      break;
    case kRight:
      n = {-1, 0};
      break;
  }
  const double approach = -((s.vx - vw.x) * n.x + (s.vz - vw.z) * n.z);  // > 0 approaching
  const bool pushes = wallPushes(wall, now_);
  const bool resting = pushes && std::abs(approach) <= restSpeed(wallPress(wall));
  if (approach <= 0.0 && !resting) {  // separating: the event was a grazing near-miss
    predict(i);
    return;
  }
  const double before = particleEnergy(s);
  if (approach > 0.0) {
    const bool elastic = tcElastic(i, -1);
    const double e_n = elastic ? 1.0 : cfg_.restitution(approach);
    const WallCollisionResult c =
        collideWall(n, {s.vx, s.vz}, s.omega, vw, cfg_.mass, cfg_.diameter, e_n, cfg_.tangential,
                    elastic ? cfg_.tc_tangential : cfg_.wall_tangential);
    // Loss in the wall's frame (the wall's own velocity is unchanged by the impact):
    // kinetic energy relative to the wall before minus after.
    const double m = cfg_.mass;
    const double inertia = m * cfg_.diameter * cfg_.diameter / 10.0;
    const double rel_before =
        0.5 * m * ((s.vx - vw.x) * (s.vx - vw.x) + (s.vz - vw.z) * (s.vz - vw.z)) +
        0.5 * inertia * s.omega * s.omega;
    const double rel_after =
        0.5 * m * ((c.v.x - vw.x) * (c.v.x - vw.x) + (c.v.z - vw.z) * (c.v.z - vw.z)) +
        0.5 * inertia * c.w * c.w;
    obs_.dissipated_energy += rel_before - rel_after;
    obs_.wall_dissipated_energy += rel_before - rel_after;
    if (wall == kBottom) bottom_impulse_ += m * (c.v.z - s.vz);
    s.vx = c.v.x;
    s.vz = c.v.z;
    s.omega = c.w;
    ++obs_.collisions.wall;
    if (elastic) ++obs_.collisions.tc_elastic;
    noteRattle(i, approach);
    noteCollision(i, -1);
    obs_.wall_work += particleEnergy(s) - before + (rel_before - rel_after);
  } else {
    ++s.counter;
  }
  // Rest on (ride) the wall if the particle would leave it too slowly to matter while the
  // wall pushes it: it then moves with the wall until the wall's pull exceeds gravity.
  const double separation = (s.vx - vw.x) * n.x + (s.vz - vw.z) * n.z;
  const Motion rigid = wall == kBottom ? Motion::RideBottom : Motion::RideLid;
  if ((wall == kBottom || wall == kLid) && pushes &&
      (separation <= restSpeed(wallPress(wall)) || pinched(i, n, rigid, -1))) {
    startRiding(i, wall);
  } else if (s.motion != Motion::Ballistic && (s.vz != plateAt(now_).velocity)) {
    s.motion = Motion::Ballistic;  // a rough side wall changed its vertical velocity
    wakeRestingOn(i);
  }
  sleepIfAtRest(i);
  predict(i);
}

void EdSimulation::startRiding(int i, WallId wall) {
  ParticleState& s = p_[i];
  const double before = particleEnergy(s);
  const double zb = plateAt(now_).height;
  s.ride_offset = wall == kBottom ? 0.5 * cfg_.diameter : cfg_.height - 0.5 * cfg_.diameter;
  s.z = zb + s.ride_offset;
  s.motion = wall == kBottom ? Motion::RideBottom : Motion::RideLid;
  bookBottomImpulse(s, plateAt(now_).velocity - s.vz);
  s.vz = plateAt(now_).velocity;
  // The residual normal motion (at most rest_velocity) is absorbed: count it as loss.
  const double after = particleEnergy(s);
  obs_.dissipated_energy += before - after;
  obs_.wall_dissipated_energy += before - after;
  ++obs_.collisions.rests;
}

void EdSimulation::doTakeOff(int i) {
  advance(i, now_);
  p_[i].motion = Motion::Ballistic;
  ++p_[i].counter;
  predict(i);
}

void EdSimulation::doCross(int i, CrossDirection dir) {
  advance(i, now_);
  ParticleState& s = p_[i];
  const CellGeometry& g = cells_.geometry();
  const int c = cells_.cellOf(i);
  int cx = cells_.cx(c), cz = cells_.cz(c);
  switch (dir) {
    case kCrossXPlus:
      ++cx;
      break;
    case kCrossXMinus:
      --cx;
      break;
    case kCrossZPlus:
      ++cz;
      break;
    case kCrossZMinus:
      --cz;
      break;
  }
  if (cx >= g.nx) {
    cx = 0;
    s.x -= g.lx();
  }
  if (cx < 0) {
    cx = g.nx - 1;
    s.x += g.lx();
  }
  if (cz >= g.nz) {
    cz = 0;
    s.z -= g.lz();
  }
  if (cz < 0) {
    cz = g.nz - 1;
    s.z += g.lz();
  }
  cells_.remove(i);
  cells_.insert(i, cells_.index(cx, cz));
  if (!incremental_crossings_ || pair_ev_[i].time == -std::numeric_limits<double>::infinity()) {
    predict(i);
    return;
  }
  // The trajectory is unchanged: the earliest pair event found before still bounds every
  // pair of the cells that stay adjacent (stale or not: a stale one re-predicts in full when
  // it comes due, as any stale event). Only the newly adjacent cells need testing.
  const int step_x = dir == kCrossXPlus ? 1 : dir == kCrossXMinus ? -1 : 0;
  const int step_z = dir == kCrossZPlus ? 1 : dir == kCrossZMinus ? -1 : 0;
  CellGrid::Neighbour nb[3];
  const int m = cells_.newNeighbours(cells_.cellOf(i), step_x, step_z, nb);
  Event pair = pair_ev_[i];
  predictPairs(i, s, nb, m, pair);
  schedule(i, s, pair);
}

}  // namespace granwave
