#pragma once
// The one scheduled event of a particle. Lazy invalidation (DynamO, Smallenburg): a pair
// event stores the partner's collision counter at prediction time; if the partner has
// collided since, the event is stale and the particle is simply re-predicted.
#include <cstdint>
#include <limits>

namespace granwave {

enum class EventKind : std::uint8_t {
  None,
  Pair,       // partner = other particle
  Wall,       // partner = WallId
  CellCross,  // partner = CrossDirection
  TakeOff,    // a particle riding a wall leaves it
};

enum WallId : std::int32_t { kBottom = 0, kLid = 1, kLeft = 2, kRight = 3 };
enum CrossDirection : std::int32_t { kCrossXMinus = 0, kCrossXPlus, kCrossZMinus, kCrossZPlus };

struct Event {
  double time = std::numeric_limits<double>::infinity();
  EventKind kind = EventKind::None;
  std::int32_t partner = -1;
  std::uint32_t partner_counter = 0;
};

}  // namespace granwave
