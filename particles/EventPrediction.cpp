// Prediction ("when"): the earliest event of one particle given everyone's current
// trajectories. Const with respect to the state; only ev_ and the queue are written.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "particles/EdSimulation.hpp"
#include "particles/GapRootFinder.hpp"
#include "particles/PairCollisionTime.hpp"

namespace granwave {

namespace {

inline void consider(Event& best, double t, EventKind kind, int partner,
                     std::uint32_t counter = 0) {
  if (t < best.time) best = {t, kind, partner, counter};
}

// Rising through z_hi under gravity: first root of z + v tau - g tau^2/2 = z_hi, v > 0.
inline double riseTime(double gap, double v, double g) {
  if (v <= 0.0) return std::numeric_limits<double>::infinity();
  if (gap <= 0.0) return 0.0;
  const double disc = v * v - 2.0 * g * gap;
  if (disc < 0.0) return std::numeric_limits<double>::infinity();
  return 2.0 * gap / (v + std::sqrt(disc));
}

// Falling through z_lo: positive root of z + v tau - g tau^2/2 = z_lo.
inline double fallTime(double gap, double v, double g) {
  if (g <= 0.0) {
    if (v >= 0.0) return std::numeric_limits<double>::infinity();
    return std::max(0.0, gap) / -v;
  }
  const double disc = std::max(0.0, v * v + 2.0 * g * gap);
  return (v + std::sqrt(disc)) / g;
}

// Largest cell block whose members predictPairs gathers into arrays on the stack. Disks that do
// not overlap fit at most 8 to a square of side < 2d (cells are narrower than 2d), so a block
// never grows past 15; a larger one is walked cell by cell.
constexpr int kGatherCapacity = 15;

// Up to this many partners (a dilute gas, or the 3 new cells after a crossing) they are tested
// one by one: the filter of keptPartners pays where a prediction meets many partners.
constexpr int kFewPartners = 4;

// With the number of cells M and the block capacity known at compile time, the copying is
// unrolled: the stencil of a prediction (9 cells, 3 after a crossing) costs no loop exits.
template <int M, int Capacity>
int gatherBlocks(const CellGrid& cells, const CellGrid::Neighbour* nb, int first, int* partner,
                 unsigned char* via) {
  int n = 0;
#pragma GCC unroll 9
  for (int c = 0; c < M; ++c) {
    const std::span<const int> members = cells.members(nb[c].cell);
    std::copy_n(members.data(), Capacity, partner + n);
    std::fill_n(via + n, Capacity, static_cast<unsigned char>(first + c));
    n += static_cast<int>(members.size());
  }
  return n;
}

template <int Capacity>
int gatherBlocks(const CellGrid& cells, const CellGrid::Neighbour* nb, int m, int* partner,
                 unsigned char* via) {
  if (m == 9) return gatherBlocks<9, Capacity>(cells, nb, 0, partner, via);
  if (m == 3) return gatherBlocks<3, Capacity>(cells, nb, 0, partner, via);
  int n = 0;  // a stencil cut by a side wall, bottom or lid
  for (int c = 0; c < m; ++c)
    n += gatherBlocks<1, Capacity>(cells, nb + c, c, partner + n, via + n);
  return n;
}

// The members of the m cells nb into partner, with the index of the cell each came through
// into via; returns their number.
int gatherPartners(const CellGrid& cells, const CellGrid::Neighbour* nb, int m, int* partner,
                   unsigned char* via) {
  if (cells.capacity() == 3) return gatherBlocks<3>(cells, nb, m, partner, via);
  if (cells.capacity() == 7) return gatherBlocks<7>(cells, nb, m, partner, via);
  return gatherBlocks<kGatherCapacity>(cells, nb, m, partner, via);
}

// Position and velocity of s relative to the flyer q at time t0, q seen through `cell` (its
// periodic image). One definition for the filter and the test of predictPairs: the filter's
// guarantee (no partner that could change the best event is dropped) needs the same numbers.
struct Relative {
  double rx, rz, vx, vz;
};
inline Relative relativeToFlyer(const ParticleState& s, const ParticleState& q,
                                const CellGrid::Neighbour& cell, double g, double t0) {
  const double dt = t0 - q.t;
  return {s.x - (q.x + q.vx * dt) - cell.shift_x,
          s.z - (q.z + (q.vz - 0.5 * g * dt) * dt) - cell.shift_z, s.vx - q.vx,
          s.vz - (q.vz - g * dt)};
}

// What keptPartners needs to know of the particle being predicted and of its best event.
struct PairFilter {
  const ParticleState& s;
  int i;
  double g, d, t0, best_time;
};

// Indices k of the partners (partner[k], through cell nb[via[k]]) that could change the best
// event of a flyer: riders (they take the general path), and flyers approaching (b < 0) on a
// path that meets (disc >= 0) no later than the best event so far. Since f(t) = c + 2 b t + a
// t^2 is convex, a root at tau <= T needs c + 2 b tau <= 0, so c <= -2 b T (trivially true for a
// pair touching now, c <= 0); for c > 0 the computed root c / (-b + sqrt(disc)) is >= c / (-2 b)
// in floating point too, and T is widened past the rounding of t0 + tau < best. Every test is
// folded into one sum, so the loop has no branch but its exit: tested one by one, partners
// cost the wet scene half its mispredicted branches (docs/performance.md). The margins on disc
// and c (far beyond round-off, far below any gap that matters) keep the filter on the safe
// side where a build contracts a * b + c into fused multiply-adds differently here and in
// pairCollisionTime; they keep a few more partners, which the test then rejects.
int keptPartners(const PairFilter& f, const std::vector<ParticleState>& p,
                 const CellGrid::Neighbour* nb, const int* partner, const unsigned char* via, int n,
                 int* kept) {
  const double horizon = std::max(0.0, f.best_time - f.t0);
  const double reach = horizon * (1.0 + 1e-12) + 1e-15 * std::abs(f.best_time);
  const ParticleState& s = f.s;
  int n_kept = 0;
  for (int k = 0; k < n; ++k) {
    const int j = partner[k];
    const ParticleState& q = p[j];
    const CellGrid::Neighbour& cell = nb[via[k]];
    const auto [rx, rz, vx, vz] = relativeToFlyer(s, q, cell, f.g, f.t0);
    const double b = rx * vx + rz * vz;
    const double c = rx * rx + rz * rz - f.d * f.d;
    const double disc = b * b - (vx * vx + vz * vz) * c;
    const bool meets = (b < 0.0) & (disc >= -1e-9 * (b * b)) &
                       (c <= -2.0 * b * reach + kTouchingSlack * f.d * f.d);
    kept[n_kept] = k;
    n_kept += (j != f.i) & ((q.motion != Motion::Ballistic) | meets);
  }
  return n_kept;
}

}  // namespace

void EdSimulation::predict(int i) {
  const ParticleState s = extrapolated(i, now_);
  Event crossing;
  predictCrossing(i, s, crossing);
  CellGrid::Neighbour nb[9];
  const int m = cells_.neighbours(cells_.cellOf(i), nb);
  // Unless pair events are carried over crossings, the particle is predicted afresh at its
  // next crossing: no pair event after it can be its next event, and a pair at the same time
  // loses to it (precedence below). The search is bounded there: keptPartners drops the
  // partners met later, and root searches with riders stop there.
  Event pair;
  if (!incremental_crossings_) pair.time = crossing.time;
  predictPairs(i, s, nb, m, pair);
  schedule(i, s, pair, crossing);
}

void EdSimulation::schedule(int i, const ParticleState& s, const Event& pair) {
  Event crossing;
  predictCrossing(i, s, crossing);
  schedule(i, s, pair, crossing);
}

void EdSimulation::schedule(int i, const ParticleState& s, const Event& pair,
                            const Event& crossing) {
  pair_ev_[i] = pair;
  // Precedence at equal times: crossing, then walls, then pairs. The wall root finders need
  // to look no further than the earliest event found so far.
  Event best = crossing;
  predictWalls(i, s, best, std::min(best.time, pair.time));
  if (pair.time < best.time) best = pair;
  ev_[i] = best;
  queue_.update(i, best.time);
}

void EdSimulation::predictCrossing(int i, const ParticleState& s, Event& best) const {
  const CellGeometry& g = cells_.geometry();
  const int c = cells_.cellOf(i);
  const int cx = cells_.cx(c), cz = cells_.cz(c);
  const double xlo = cells_.xLow(c), zlo = cells_.zLow(c);
  if (s.vx > 0.0 && (g.periodic_x || cx + 1 < g.nx))
    consider(best, now_ + std::max(0.0, xlo + g.wx - s.x) / s.vx, EventKind::CellCross,
             kCrossXPlus);
  if (s.vx < 0.0 && (g.periodic_x || cx > 0))
    consider(best, now_ + std::max(0.0, s.x - xlo) / -s.vx, EventKind::CellCross, kCrossXMinus);

  const bool up_open = g.periodic_z || cz + 1 < g.nz;
  const bool down_open = g.periodic_z || cz > 0;
  if (s.motion == Motion::Ballistic && cfg_.gravity == 0.0) {  // straight lines (a gas)
    if (up_open && s.vz > 0.0)
      consider(best, now_ + std::max(0.0, zlo + g.wz - s.z) / s.vz, EventKind::CellCross,
               kCrossZPlus);
    if (down_open && s.vz < 0.0)
      consider(best, now_ + std::max(0.0, s.z - zlo) / -s.vz, EventKind::CellCross, kCrossZMinus);
    return;
  }
  if (s.motion == Motion::Ballistic) {
    if (up_open)
      consider(best, now_ + riseTime(zlo + g.wz - s.z, s.vz, cfg_.gravity), EventKind::CellCross,
               kCrossZPlus);
    if (down_open)
      consider(best, now_ + fallTime(s.z - zlo, s.vz, cfg_.gravity), EventKind::CellCross,
               kCrossZMinus);
    return;
  }
  // Riding: the height is the wall's, z(t) = A sin(w t) + offset, so a boundary z_c is
  // crossed where sin(w t) passes (z_c - offset) / A: rising at the phase asin of it,
  // falling at pi minus that, once a cycle, and never if |z_c - offset| >= A. (A bounded-
  // curvature root search here ran to its step limit, a sine and cosine a step, for every
  // rider that never crosses: the whole cost of a resting layer on a gently shaken plate.)
  if (up_open)
    consider(best, riderCrossingTime(zlo + g.wz - s.ride_offset, true), EventKind::CellCross,
             kCrossZPlus);
  if (down_open)
    consider(best, riderCrossingTime(zlo - s.ride_offset, false), EventKind::CellCross,
             kCrossZMinus);
}

double EdSimulation::riderCrossingTime(double u, bool rising) const {
  const PlateMotion& plate = cfg_.plate;
  if (!(plate.omega > 0.0) || !(std::abs(u) < plate.amplitude))
    return std::numeric_limits<double>::infinity();
  const double two_pi = 2.0 * std::numbers::pi;
  const double a = std::asin(u / plate.amplitude);
  const double phase = rising ? a : std::numbers::pi - a;
  const double k = std::ceil((plate.omega * now_ - phase) / two_pi);
  double t = (phase + k * two_pi) / plate.omega;
  if (t < now_) t = (phase + (k + 1) * two_pi) / plate.omega;
  return t;
}

void EdSimulation::predictWalls(int i, const ParticleState& s, Event& best, double horizon) const {
  (void)i;
  const double r = 0.5 * cfg_.diameter;
  if (!cfg_.periodic_x) {
    if (s.vx < 0.0) consider(best, now_ + std::max(0.0, s.x - r) / -s.vx, EventKind::Wall, kLeft);
    if (s.vx > 0.0)
      consider(best, now_ + std::max(0.0, cfg_.width - r - s.x) / s.vx, EventKind::Wall, kRight);
  }
  if (cfg_.periodic_z) return;

  const PlateMotion& plate = cfg_.plate;
  const double g = cfg_.gravity;
  if (s.motion != Motion::Ballistic) {
    // Riding ends where the wall stops pushing: bottom while sin(wt) < g/(A w^2), lid while
    // sin(wt) > g/(A w^2) (see wallPushes).
    const double aw2 = plate.maxAcceleration();
    if (aw2 <= g || plate.omega <= 0.0) return;  // the bottom holds forever, the lid never
    const double phi_star = std::asin(g / aw2);
    const double phi_leave =
        s.motion == Motion::RideBottom ? phi_star : std::numbers::pi - phi_star;
    const double two_pi = 2.0 * std::numbers::pi;
    const double phase = plate.omega * now_;
    double k = std::ceil((phase - phi_leave) / two_pi);
    double t = (phi_leave + k * two_pi) / plate.omega;
    if (t <= now_) t = (phi_leave + (k + 1) * two_pi) / plate.omega;
    consider(best, t, EventKind::TakeOff, -1);
    return;
  }
  predictBottomAndLid(s, best, std::min(horizon, best.time));
}

void EdSimulation::predictBottomAndLid(const ParticleState& s, Event& best, double horizon) const {
  const double r = 0.5 * cfg_.diameter;
  const PlateMotion& plate = cfg_.plate;
  const double g = cfg_.gravity;
  const double t0 = now_;
  const double tol = 1e-10 * cfg_.diameter;
  // The plate never leaves [-A, A]: a particle whose own parabola stays more than d/2 (plus a
  // margin far above round-off) clear of that band until the horizon cannot meet the wall
  // before it, and the root finder, which would return "never", is not asked (it costs a sin
  // and a cos per step).
  const double margin = 1e-9 * cfg_.diameter, A = plate.amplitude;
  const double tau_h = horizon - t0;
  bool bottom = true, lid = true;
  if (std::isfinite(tau_h) && g > 0.0) {
    const double z_end = s.z + (s.vz - 0.5 * g * tau_h) * tau_h;
    const double z_top =
        s.vz > 0.0 && s.vz < g * tau_h ? s.z + s.vz * s.vz / (2.0 * g) : std::max(s.z, z_end);
    bottom = std::min(s.z, z_end) - r - A <= margin;
    lid = cfg_.height - A - r - z_top <= margin;
  }
  if (!bottom && !lid) return;
  const PlateState& plate0 = plateAt(t0);
  const double zb0 = plate0.height, vb0 = plate0.velocity;
  // Bottom: h = z(t) - d/2 - z_b(t), h'' = -g - z_b'' >= -(g + A w^2).
  if (bottom) {
    auto gap = [&](double t) {
      const double tau = t - t0;
      return GapRate{s.z + (s.vz - 0.5 * g * tau) * tau - r - plate.height(t),
                     s.vz - g * tau - plate.velocity(t)};
    };
    const GapRate h0{s.z - r - zb0, s.vz - vb0};
    if (h0.h <= tol && wallPushes(kBottom, t0) &&
        std::abs(h0.rate) <= restSpeed(wallPress(kBottom))) {
      consider(best, t0, EventKind::Wall, kBottom);  // resting contact: starts riding
    } else {
      consider(best, firstClosingRoot(gap, bottom_curvature_, t0, horizon, {tol}, h0),
               EventKind::Wall, kBottom);
    }
  }
  // Lid: h = z_b(t) + L_z - d/2 - z(t), h'' = z_b'' + g >= g - A w^2.
  if (lid) {
    auto gap = [&](double t) {
      const double tau = t - t0;
      return GapRate{plate.height(t) + cfg_.height - r - s.z - (s.vz - 0.5 * g * tau) * tau,
                     plate.velocity(t) - s.vz + g * tau};
    };
    const GapRate h0{zb0 + cfg_.height - r - s.z, vb0 - s.vz};
    if (h0.h <= tol && wallPushes(kLid, t0) && std::abs(h0.rate) <= restSpeed(wallPress(kLid))) {
      consider(best, t0, EventKind::Wall, kLid);
    } else {
      consider(best, firstClosingRoot(gap, lid_curvature_, t0, horizon, {tol}, h0), EventKind::Wall,
               kLid);
    }
  }
}

// The earliest pair event of i (state s, speed speed_i) with j seen through the image nb, if it
// comes before `best`.
void EdSimulation::predictPairWith(int i, const ParticleState& s, double speed_i, int j,
                                   const CellGrid::Neighbour& nb, Event& best) const {
  const double d = cfg_.diameter, g = cfg_.gravity;
  const ParticleState& q = p_[j];
  const double dt = now_ - q.t;
  double oz, ovz;
  if (q.motion == Motion::Ballistic) {
    oz = q.z + (q.vz - 0.5 * g * dt) * dt;
    ovz = q.vz - g * dt;
  } else {
    oz = plateAt(now_).height + q.ride_offset;  // sin/cos only if a rider is met
    ovz = plateAt(now_).velocity;
  }
  const double rx = s.x - (q.x + q.vx * dt) - nb.shift_x;
  const double rz = s.z - oz - nb.shift_z;
  const double vx = s.vx - q.vx, vz = s.vz - ovz;
  const bool linear =
      s.motion == q.motion || (s.motion != Motion::Ballistic && q.motion != Motion::Ballistic);
  if (linear && s.motion == q.motion && s.motion != Motion::Ballistic) {
    // Both carried by the same wall: they can only meet horizontally.
    const double tol = approachTolerance(speed_i, std::sqrt(q.vx * q.vx + ovz * ovz));
    const double tau = riderPairCollisionTime(rx, rz, vx, d, tol);
    if (now_ + tau < best.time) best = {now_ + tau, EventKind::Pair, j, q.counter};
    return;
  }
  if (linear) {
    // Same acceleration for both: the relative motion is a straight line.
    double tau = pairCollisionTime(rx, rz, vx, vz, d);
    // Touching "at once", or at a gap of round-off: only if the approach is more than
    // round-off (rare, so the tolerance, which costs square roots, is computed only here).
    if (tau == 0.0 || (std::isfinite(tau) && rx * rx + rz * rz <= d * d * (1.0 + kTouchingSlack))) {
      const double tol = approachTolerance(speed_i, std::sqrt(q.vx * q.vx + ovz * ovz));
      tau = pairCollisionTime(rx, rz, vx, vz, d, tol);
    }
    if (now_ + tau < best.time) best = {now_ + tau, EventKind::Pair, j, q.counter};
    return;
  }
  const double tol = approachTolerance(speed_i, std::sqrt(q.vx * q.vx + ovz * ovz));
  const double r2 = rx * rx + rz * rz;
  if (r2 <= d * d * (1.0 + kTouchingSlack)) {
    // Touching a rider with no relative normal motion while pressed: rests on it now.
    const double dist = std::sqrt(r2);
    const double rate = (rx * vx + rz * vz) / dist;
    ParticleState o = q;
    o.z = oz;
    const Vec2 n{rx / dist, rz / dist};  // from j to i
    const double press =
        s.motion == Motion::Ballistic ? riderPress(o, s, n) : riderPress(s, o, {-n.x, -n.z});
    // rx * vx is the same whichever of the two is the flyer.
    if (press > 0.0 && std::abs(rate) <= restSpeed(press) && !slidesIntoSupport(rx, vx)) {
      if (now_ < best.time) best = {now_, EventKind::Pair, j, q.counter};
      return;
    }
  }
  // One rides a wall, the other flies: the relative acceleration is bounded by
  // g + A w^2, and so is the curvature of the distance |r| - d (its other term is >= 0).
  // Search only until either partner's next event: both re-predict then.
  const double horizon = std::min(best.time, queue_.time(j));
  if (horizon <= now_) return;
  const double sx = nb.shift_x, sz = nb.shift_z;
  auto gap = [&](double t) {
    const ParticleState a = extrapolated(i, t);
    const ParticleState b = extrapolated(j, t);
    const double dx = a.x - b.x - sx, dz = a.z - b.z - sz;
    const double dist = std::sqrt(dx * dx + dz * dz);
    return GapRate{dist - d, (dx * (a.vx - b.vx) + dz * (a.vz - b.vz)) / dist};
  };
  const double t = firstClosingRoot(gap, pair_curvature_, now_, horizon, {1e-10 * d, tol});
  if (t < best.time) best = {t, EventKind::Pair, j, q.counter};
}

void EdSimulation::predictPairs(int i, const ParticleState& s, const CellGrid::Neighbour* nb, int m,
                                Event& best) const {
  // Two flyers share the acceleration (-g), so their relative motion is a straight line: the
  // common case (every pair of the gas, most of the paper's scenes) is tested here inline with
  // the same arithmetic as predictPairWith, and a receding pair (b >= 0, about half) costs no
  // more than its relative position and velocity. Riders, and pairs touching now or at a gap of
  // round-off (which need the round-off tolerance), take the general path.
  const double g = cfg_.gravity, d = cfg_.diameter, t0 = now_;
  const bool flyer = s.motion == Motion::Ballistic;
  double speed_i = -1.0;  // |v_i|, computed once, and only if the general path needs it
  auto speed = [&] {
    if (speed_i < 0.0) speed_i = std::sqrt(s.vx * s.vx + s.vz * s.vz);
    return speed_i;
  };
  auto test = [&](int j, const CellGrid::Neighbour& cell) {
    const ParticleState& q = p_[j];
    if (!flyer || q.motion != Motion::Ballistic) {
      if (j != i) predictPairWith(i, s, speed(), j, cell, best);
      return;
    }
    const auto [rx, rz, vx, vz] = relativeToFlyer(s, q, cell, g, t0);
    // Receding: never (pairCollisionTime). i itself is among the partners: one test for both,
    // without a branch of its own (the | is deliberate: two unpredictable branches cost more).
    if ((rx * vx + rz * vz >= 0.0) | (j == i)) return;
    const double tau = pairCollisionTime(rx, rz, vx, vz, d);
    if (tau == 0.0 ||
        (tau < best.time - t0 && rx * rx + rz * rz <= d * d * (1.0 + kTouchingSlack))) {
      predictPairWith(i, s, speed(), j, cell, best);  // the round-off tolerance decides
      return;
    }
    if (t0 + tau < best.time) best = {t0 + tau, EventKind::Pair, j, q.counter};
  };
  if (cells_.capacity() > kGatherCapacity) {
    for (int c = 0; c < m; ++c)
      for (const int j : cells_.members(nb[c].cell)) test(j, nb[c]);
    return;
  }
  // The partners of all cells in one array first: a cell's block is copied whole (its empty
  // slots are overwritten by the next cell's), so the gathering has no data-dependent branch,
  // and the loop below has one exit instead of one per cell (docs/performance.md).
  int partner[9 * kGatherCapacity];
  unsigned char via[9 * kGatherCapacity];
  const int n = gatherPartners(cells_, nb, m, partner, via);
  if (!flyer || n <= kFewPartners) {
    for (int k = 0; k < n; ++k) test(partner[k], nb[via[k]]);
    return;
  }
  // Two passes: the first keeps, without a branch, the partners that could change `best`
  // (keptPartners); the second runs `test` on them in their order, so the result is that of
  // testing every partner (docs/performance.md, "Partners filtered without branches").
  int kept[9 * kGatherCapacity];
  const PairFilter filter{s, i, g, d, t0, best.time};
  const int n_kept = keptPartners(filter, p_, nb, partner, via, n, kept);
  for (int k = 0; k < n_kept; ++k) test(partner[kept[k]], nb[via[kept[k]]]);
}

}  // namespace granwave
