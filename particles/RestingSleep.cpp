// Sleep and wake of particles at rest on the bottom (docs/physics.md, "Resting contacts",
// item 7). With the TC model on, a particle held by two or more supports (in the pocket
// between two riders, in a row between both side walls) rattles elastically for ever: every
// collision comes within t_c of its last, so none dissipates (Luding & McNamara 1998 call it
// an enduring contact). Rigid-body engines end such rattling by putting the body to sleep
// once its contacts have stayed slow for a while and waking it when something hits it
// (Box2D, Bullet: islands of bodies resting on each other); here the sleeper is carried by
// the bottom like a rider, z = z_b(t) + offset, with no horizontal motion of its own.
#include <cmath>
#include <vector>

#include "particles/EdSimulation.hpp"

namespace granwave {

void EdSimulation::noteRattle(int k, int partner, double v_n, Vec2 n_partner_to_k) {
  if (cfg_.tc <= 0.0) return;
  ParticleState& s = p_[k];
  // A fast collision breaks the streak, and so does one with a flying partner below k,
  // which is no support yet (it may still fall). A slow one counts when it is enduring: it
  // follows k's previous collision within t_c, so the TC model makes it elastic on k's
  // account. A slow one after a longer pause dissipates as usual: it neither counts nor
  // breaks the streak.
  const bool flyer_below = partner >= 0 && p_[partner].motion == Motion::Ballistic &&
                           n_partner_to_k.z > kBelow;
  const bool fast = s.motion == Motion::Ballistic && v_n > sleepSpeed();
  if (fast || flyer_below || s.motion == Motion::RideLid) {
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
    for (int j = cells_.head(nb[n].cell); j >= 0; j = cells_.next(j)) {
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
  if (p_[k].rattle < kSleepStreak) return;
  const Contacts c = contactsOf(k);
  if (wallPushes(kBottom, now_) &&
      ((c.held_left && c.held_right) || (c.bottom && !c.flyer_below))) {
    fallAsleep(k);
  } else if (c.left && c.right && p_[k].motion == Motion::Ballistic) {
    // Not held yet, but jammed sideways with no gap on either side: its horizontal rattle
    // would repeat at one instant for ever. It stops sideways (the loss is booked) and goes
    // on falling onto its supports.
    ParticleState& s = p_[k];
    const double before = particleEnergy(s);
    s.vx = 0.0;
    s.rattle = 0;
    ++s.counter;
    obs_.dissipated_energy += before - particleEnergy(s);
  }
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
      for (int j = cells_.head(nb[c].cell); j >= 0; j = cells_.next(j)) {
        // Riders at the bottom's own contact height are held by the bottom itself.
        if (j == a || p_[j].motion != Motion::RideBottom || p_[j].ride_offset <= 0.5 * d * (1 + 1e-9))
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

}  // namespace granwave

namespace granwave {

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
  const double rel_after =
      0.5 * cfg_.mass * ((ux + dvx) * (ux + dvx) + (uz + dvz) * (uz + dvz));
  s.vx += dvx;
  s.vz += dvz;
  bookBottomImpulse(c, dvz);
  obs_.dissipated_energy += rel_before - rel_after;
  obs_.wall_work += particleEnergy(s) - before + (rel_before - rel_after);
  ++obs_.collisions.pair;
  if (elastic) ++obs_.collisions.tc_elastic;
  if (impact_observer_) impact_observer_->pairImpact({now_, v_n, s.z - 0.5 * cfg_.diameter * n.z, elastic});
  noteRattle(f, r, v_n, n);
  noteCollision(f, r);
  noteCollision(r, f);
  if (press > 0.0 && e_n * v_n <= restSpeed(press)) attachToRider(f, c, {n.x * cfg_.diameter, n.z * cfg_.diameter});
  sleepIfAtRest(f);
  predict(f);
  predict(r);
}

}  // namespace granwave
