// Resting contacts (docs/physics.md, "Resting contacts"): particles coming to rest on a
// rider (item 2), and sleep and wake of particles at rest on the bottom (item 7).
//
// With the TC model on, a particle held by two or more supports (in the pocket
// between two riders, in a row between both side walls) rattles elastically for ever: every
// collision comes within t_c of its last, so none dissipates (Luding & McNamara 1998 call it
// an enduring contact). Rigid-body engines end such rattling by putting the body to sleep
// once its contacts have stayed slow for a while and waking it when something hits it
// (Box2D, Bullet: islands of bodies resting on each other); here the sleeper is carried by
// the bottom like a rider, z = z_b(t) + offset, with no horizontal motion of its own.
#include <algorithm>
#include <cmath>
#include <vector>

#include "particles/EdSimulation.hpp"

namespace granwave {

void EdSimulation::noteRattle(int k, double v_n) {
  if (cfg_.tc <= 0.0 || (!cfg_.sleep && cfg_.sleep_alarm == 0)) return;
  ParticleState& s = p_[k];
  // Collisions in a row, each within t_c of the previous one. In a fluidised layer they stay
  // short (at most 141 on the paper's wet scene over 12 seeds); a particle rattling at no gap
  // in a row or a pocket makes thousands (docs/physics.md, item 7). With the rule off they
  // raise its alarm; with it on, sleepIfAtRest ends a rattle its own conditions miss.
  s.enduring = now_ - s.last_collision < cfg_.tc ? s.enduring + 1 : 0;
  if (!sleepOn()) {
    if (s.enduring < cfg_.sleep_alarm) return;
    sleep_alarm_time_ = now_;  // the rule is on from here to the end of the run
  }
  // A collision counts when it is enduring: it follows k's previous one within t_c, so the
  // TC model makes it elastic on k's account. A flying particle's collision faster than the
  // sleep speed breaks the streak (it is being hit, not resting); a slow one after a longer
  // pause dissipates as usual and neither counts nor breaks it. A carried particle moves
  // only sideways, at no gap from its neighbours when it rattles: any enduring collision
  // counts.
  if (s.motion == Motion::RideLid || (s.motion == Motion::Ballistic && v_n > sleepSpeed())) {
    s.rattle = 0;
    return;
  }
  if (now_ - s.last_collision < cfg_.tc && s.rattle < kSleepStreak) ++s.rattle;
}

EdSimulation::Contacts EdSimulation::contactsOf(int k) const {
  const ParticleState& s = p_[k];
  const double d = cfg_.diameter, tol = kContactGap * d;
  Contacts c;
  c.bottom = s.motion == Motion::RideBottom || s.z - 0.5 * d - plateAt(now_).height <= tol;
  c.held_left = c.left = !cfg_.periodic_x && s.x - 0.5 * d <= tol;
  c.held_right = c.right = !cfg_.periodic_x && cfg_.width - 0.5 * d - s.x <= tol;
  const double reach2 = (d + tol) * (d + tol);
  CellGrid::Neighbour nb[9];
  const int m = cells_.neighbours(cells_.cellOf(k), nb);
  for (int n = 0; n < m; ++n) {
    for (const int j : cells_.members(nb[n].cell)) {
      if (j == k) continue;
      const ParticleState o = extrapolated(j, now_);
      const double rx = s.x - o.x - nb[n].shift_x, rz = s.z - o.z - nb[n].shift_z;
      if (rx * rx + rz * rz > reach2) continue;
      const bool from_below = rz > kBelow * d, level = std::abs(rz) <= kBelow * d;
      c.left = c.left || (level && rx > 0.0);
      c.right = c.right || (level && rx < 0.0);
      if (o.motion == Motion::Ballistic) {
        c.flyer_below = c.flyer_below || from_below;
      } else if (o.motion == Motion::RideBottom) {
        c.bottom = c.bottom || from_below;
        c.held_left = c.held_left || rx > 0.0;
        c.held_right = c.held_right || rx < 0.0;
      }
    }
  }
  return c;
}

void EdSimulation::sleepIfAtRest(int k) {
  // Held by the bottom, directly or through what it carries, while the bottom pushes
  // (z_b'' > -g): wedged between carried particles or side walls on both sides (a particle
  // in a row that fills the box exactly, held there by its side contacts), or touching the
  // bottom or a carried particle from above and no flying particle from below (which is no
  // support: it may still fall).
  if (!sleepOn()) return;
  if (cfg_.sleep_alarm > 0 && p_[k].enduring >= cfg_.sleep_alarm) {
    // Still rattling at no gap with the rule on (e.g. flyers swapping their horizontal
    // velocities between two riders at one instant, each hit faster than the sleep speed,
    // which breaks the streak): the contact has lasted sleep_alarm t_c at most, far longer
    // than the soft contact the TC model stands for would keep its relative motion. Its
    // group collides perfectly inelastically.
    moveTogether(k);
    return;
  }
  if (p_[k].rattle < kSleepStreak) return;
  const Contacts c = contactsOf(k);
  if (wallPushes(kBottom, now_) &&
      ((c.held_left && c.held_right) || (c.bottom && !c.flyer_below))) {
    fallAsleep(k);
  } else if (p_[k].motion == Motion::Ballistic && c.left && c.right) {
    moveTogether(k);
  }
}

void EdSimulation::moveTogether(int k) {
  // Not held yet, but jammed sideways (touching something level with it on both sides):
  // k and the flying particles connected to it through contacts stop moving
  // relative to each other, and relative to the bottom if they touch something it holds (a
  // side wall or a carried particle): a perfectly inelastic collision of the group, its
  // kinetic energy (relative to the holder) booked as loss. Otherwise a group jammed at no
  // gap, e.g. a row between a carried particle and a side wall, would rattle at one
  // instant for ever. It goes on falling as one onto its supports.
  const double d = cfg_.diameter, reach2 = d * d * (1.0 + kContactGap) * (1.0 + kContactGap);
  // The group: every flying particle connected to k through touching flying particles;
  // held if one of them touches the bottom, a side wall or a carried particle.
  std::vector<int> group{k};
  in_group_.resize(p_.size(), 0);  // all 0 between calls: only members are set, and reset below
  in_group_[k] = 1;
  bool held = p_[k].motion != Motion::Ballistic;  // a carried k: the bottom holds the group
  for (std::size_t g = 0; g < group.size(); ++g) {
    const int a = group[g];
    const ParticleState s = extrapolated(a, now_);
    const double tol = kContactGap * d;
    held = held || s.z - 0.5 * d - plateAt(now_).height <= tol ||
           (!cfg_.periodic_x && (s.x - 0.5 * d <= tol || cfg_.width - 0.5 * d - s.x <= tol));
    CellGrid::Neighbour nb[9];
    const int m = cells_.neighbours(cells_.cellOf(a), nb);
    for (int n = 0; n < m; ++n) {
      for (const int j : cells_.members(nb[n].cell)) {
        if (j == a || in_group_[j]) continue;
        const ParticleState o = extrapolated(j, now_);
        const double rx = s.x - o.x - nb[n].shift_x, rz = s.z - o.z - nb[n].shift_z;
        if (rx * rx + rz * rz > reach2) continue;
        if (o.motion == Motion::Ballistic) {
          group.push_back(j);
          in_group_[j] = 1;
        } else {
          held = true;
        }
      }
    }
  }
  double vx = 0, vz = 0, before = 0;
  for (int j : group) {
    advance(j, now_);
    vx += p_[j].vx;
    vz += p_[j].vz;
    before += particleEnergy(p_[j]);
  }
  vx = held ? 0.0 : vx / static_cast<double>(group.size());
  vz = held ? plateAt(now_).velocity : vz / static_cast<double>(group.size());
  double after = 0;
  for (int j : group) {
    in_group_[j] = 0;
    p_[j].vx = vx;
    p_[j].vz = vz;
    p_[j].rattle = 0;
    p_[j].enduring = 0;
    ++p_[j].counter;
    after += particleEnergy(p_[j]);
    if (j != k) predict(j);
  }
  obs_.dissipated_energy += before - after;
}

void EdSimulation::fallAsleep(int k) {
  // k is carried rigidly by the bottom from now on: its motion relative to the plate (at
  // most the sleep speed) is absorbed, booked as dissipation, and the vertical part of it
  // as an impulse of the bottom, through whatever k rests on.
  ParticleState& s = p_[k];
  const double before = particleEnergy(s);
  const double vb = plateAt(now_).velocity;
  if (s.motion == Motion::Ballistic) {
    s.motion = Motion::RideBottom;
    s.ride_offset = s.z - plateAt(now_).height;
  }
  bookBottomImpulse(s, vb - s.vz);
  s.vx = 0.0;
  s.vz = vb;
  s.omega = 0.0;
  s.rattle = 0;
  s.enduring = 0;
  ++s.counter;
  obs_.dissipated_energy += before - particleEnergy(s);
  ++sleeps_;
}

void EdSimulation::wakeRestingOn(int k) {
  // Breadth-first over the riders touching a particle that no longer rides from above:
  // nothing holds them any more, so they fly on with their velocity (the plate's).
  const double d = cfg_.diameter, reach2 = d * d * (1.0 + 2e-6);
  std::vector<int> open{k};
  while (!open.empty()) {
    const int a = open.back();
    open.pop_back();
    const ParticleState s = extrapolated(a, now_);
    CellGrid::Neighbour nb[9];
    const int m = cells_.neighbours(cells_.cellOf(a), nb);
    for (int c = 0; c < m; ++c) {
      for (const int j : cells_.members(nb[c].cell)) {
        // Riders at the bottom's own contact height are held by the bottom itself.
        if (j == a || p_[j].motion != Motion::RideBottom ||
            p_[j].ride_offset <= 0.5 * d * (1 + 1e-9))
          continue;
        const ParticleState o = extrapolated(j, now_);
        const double rx = o.x + nb[c].shift_x - s.x, rz = o.z + nb[c].shift_z - s.z;
        if (rx * rx + rz * rz > reach2 || !(rz > 0.0)) continue;
        advance(j, now_);
        p_[j].motion = Motion::Ballistic;
        p_[j].rattle = 0;
        ++p_[j].counter;
        predict(j);
        open.push_back(j);
      }
    }
  }
}

void EdSimulation::bounceOffCarried(int f, int r, Vec2 n, double v_n, double press) {
  // A slow impact on a particle the bottom carries (v_n at most the sleep speed): the bottom
  // takes it, through the carried particle, which keeps its motion (it wakes only when hit
  // faster). The flyer bounces as off a wall moving with the carried particle, smooth.
  ParticleState& s = p_[f];
  ParticleState& c = p_[r];
  const bool elastic = tcElastic(f, r);
  const double e_n = elastic ? 1.0 : cfg_.restitution(v_n);
  if (!elastic) bookImpact(v_n, e_n);
  const double before = particleEnergy(s);
  const double ux = s.vx - c.vx, uz = s.vz - c.vz;
  const double un = ux * n.x + uz * n.z;  // -v_n
  const double rel_before = 0.5 * cfg_.mass * (ux * ux + uz * uz);
  const double dvx = -(1.0 + e_n) * un * n.x, dvz = -(1.0 + e_n) * un * n.z;
  const double rel_after = 0.5 * cfg_.mass * ((ux + dvx) * (ux + dvx) + (uz + dvz) * (uz + dvz));
  s.vx += dvx;
  s.vz += dvz;
  bookBottomImpulse(c, dvz);
  obs_.dissipated_energy += rel_before - rel_after;
  obs_.wall_work += particleEnergy(s) - before + (rel_before - rel_after);
  ++obs_.collisions.pair;
  if (elastic) ++obs_.collisions.tc_elastic;
  if (impact_observer_)
    impact_observer_->pairImpact({now_, v_n, s.z - 0.5 * cfg_.diameter * n.z, elastic});
  noteRattle(f, v_n);
  noteCollision(f, r);
  noteCollision(r, f);
  if (press > 0.0 && e_n * v_n <= restSpeed(press))
    attachToRider(f, c, {n.x * cfg_.diameter, n.z * cfg_.diameter});
  sleepIfAtRest(f);
  predict(f);
  predict(r);
}

bool EdSimulation::attachToRider(int i, ParticleState& rider, Vec2 r_rider_to_i) {
  // A particle at rest on a rider that presses it moves rigidly with the rider's wall (a
  // resting layer on a plate); the residual normal motion, at most rest_velocity, is lost.
  // With friction, static friction makes the pair slide together (common horizontal
  // velocity, momentum conserved); without it, a particle sliding into its support would
  // graze it at once, so it stays in flight.
  ParticleState& s = p_[i];
  if (slidesIntoSupport(r_rider_to_i.x, s.vx - rider.vx)) return false;
  const double before = particleEnergy(s) + particleEnergy(rider);
  if (cfg_.tangential.friction > 0.0 && asleep(rider)) {
    // On a sleeper, which the bottom holds still, static friction stops it: it sleeps too.
    s.vx = 0.0;
    s.omega = 0.0;
  } else if (cfg_.tangential.friction > 0.0) {
    const double vx = 0.5 * (s.vx + rider.vx);
    s.vx = vx;
    rider.vx = vx;
  }
  s.motion = rider.motion;
  s.ride_offset = s.z - plateAt(now_).height;
  bookBottomImpulse(s, plateAt(now_).velocity - s.vz);
  s.vz = plateAt(now_).velocity;
  obs_.dissipated_energy += before - particleEnergy(s) - particleEnergy(rider);
  ++obs_.collisions.rests;
  return true;
}

// After an impact involving a rider (i's partner j; n from j to i, r = x_i - x_j): the other
// particle comes to rest on a pressing rider or is pinched against it and joins the rigid layer;
// otherwise a rider given a vertical impulse leaves its wall.
void EdSimulation::settleRiders(int i, int j, Vec2 n, Vec2 r, double press, double separation) {
  const bool pressed = press > 0.0;
  ParticleState& a = p_[i];
  ParticleState& b = p_[j];
  const bool a_rides = a.motion != Motion::Ballistic, b_rides = b.motion != Motion::Ballistic;
  const double rx = r.x, rz = r.z;
  bool attached = false;
  if (pressed && separation <= restSpeed(press)) {
    // Came to rest on a pressing rider: the rider's support takes the impulse, the other
    // particle joins the rigid layer on the wall.
    ParticleState& rider = a_rides ? a : b;
    const double before_rider = particleEnergy(rider);
    bookBottomImpulse(rider, plateAt(now_).velocity - rider.vz);
    rider.vz = plateAt(now_).velocity;
    obs_.dissipated_energy += before_rider - particleEnergy(rider);
    attached = a_rides ? attachToRider(j, a, {-rx, -rz}) : attachToRider(i, b, {rx, rz});
  }
  if (!attached && pressed) {
    // A flyer pressed by a rider into another rider of the same wall is pinched between two
    // bodies that move together: it joins them (a flyer pinched against the wall itself is
    // caught in doWall).
    ParticleState& rider = a_rides ? a : b;
    const int flyer = a_rides ? j : i;
    const Vec2 away = a_rides ? Vec2{-n.x, -n.z} : Vec2{n.x, n.z};  // rider -> flyer
    if (pinched(flyer, away, rider.motion, a_rides ? i : j)) {
      const double before_rider = particleEnergy(rider);
      bookBottomImpulse(rider, plateAt(now_).velocity - rider.vz);
      rider.vz = plateAt(now_).velocity;
      obs_.dissipated_energy += before_rider - particleEnergy(rider);
      attached = attachToRider(flyer, rider, a_rides ? Vec2{-rx, -rz} : Vec2{rx, rz});
    }
  }
  if (!attached) {
    // A collision with a vertical impulse knocks riders off their wall; one pushed into the
    // wall hits it at once (and rests again if the wall still pushes it).
    if (a_rides && a.vz != plateAt(now_).velocity) {
      a.motion = Motion::Ballistic;
      wakeRestingOn(i);
    }
    if (b_rides && b.vz != plateAt(now_).velocity) {
      b.motion = Motion::Ballistic;
      wakeRestingOn(j);
    }
  }
}

bool EdSimulation::pinched(int i, Vec2 away, Motion rigid, int exclude) const {
  // Does a particle carried rigidly with the same wall (`rigid`) touch i on the side `away`?
  // Then i, pushed against the wall (or another rider) from the other side, has no room to
  // move: bouncing between two bodies that move together would repeat at one instant.
  const ParticleState& s = p_[i];
  const double d2 = cfg_.diameter * cfg_.diameter * (1.0 + 2e-9);
  CellGrid::Neighbour nb[9];
  const int m = cells_.neighbours(cells_.cellOf(i), nb);
  for (int c = 0; c < m; ++c) {
    for (const int j : cells_.members(nb[c].cell)) {
      if (j == i || j == exclude || p_[j].motion != rigid) continue;
      const ParticleState o = extrapolated(j, now_);
      const double rx = o.x + nb[c].shift_x - s.x, rz = o.z + nb[c].shift_z - s.z;
      if (rx * rx + rz * rz <= d2 && rx * away.x + rz * away.z > 0.0) return true;
    }
  }
  return false;
}

}  // namespace granwave
