#pragma once
// The engine's complete dynamic state: what a checkpoint must hold for a restored run to
// continue bit-identically. Particles are advanced lazily (each carries its own time), the
// cell lists decide between pair events at exactly equal times and a crossing reuses the
// earliest pair event found before, so all of them are kept as stored, not recomputed; the
// queue is rebuilt from its keys (its order is a function of them). Everything else (cell
// geometry, curvature bounds) follows from the EngineConfig.
#include <cstdint>
#include <vector>

#include "particles/CellGrid.hpp"
#include "particles/Event.hpp"
#include "particles/EventQueue.hpp"
#include "particles/ParticleState.hpp"
#include "particles/Snapshot.hpp"

namespace granwave {

struct EngineState {
  std::vector<ParticleState> particles;
  std::vector<Event> events;  // each particle's one scheduled event
  // Each particle's earliest pair event at its last prediction (EdSimulation::pair_ev_);
  // empty in states saved before it existed (then re-predicted in full at the next crossing).
  std::vector<Event> pair_events;
  EventQueue::Layout queue;
  CellGrid::Lists cells;
  Observables observables;  // cumulative counters (the per-record ones are recomputed)
  double now = 0;           // s
  std::uint64_t records = 0;
  double next_record = 0;  // s
  double virial = 0, virial_since = 0;
  // Cumulative vertical impulse the bottom gave the particles (N s; EdSimulation::
  // bottomImpulse) and the number of particles put to sleep; 0 in states saved before.
  double bottom_impulse = 0;
  std::uint64_t sleeps = 0;
  // When the sleep rule's alarm switched it on (s); negative if it did not, or in states
  // saved before the alarm existed.
  double sleep_alarm_time = -1.0;
};

}  // namespace granwave
