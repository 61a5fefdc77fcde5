#pragma once
// Future-event list: an indexed binary min-heap holding exactly one entry per particle,
// keyed by that particle's next event time. Updating a particle's time re-sifts its entry
// (O(log N)); there are never stale heap entries, only stale events (see Event.hpp).
#include <cstdint>
#include <vector>

namespace granwave {

class EventQueue {
 public:
  explicit EventQueue(int particles = 0);
  void reset(int particles);  // all keys +inf

  int top() const { return heap_[0]; }
  double topTime() const { return key_[heap_[0]]; }
  double time(int id) const { return key_[id]; }
  void update(int id, double time);
  int size() const { return static_cast<int>(heap_.size()); }

 private:
  void siftUp(int pos);
  void siftDown(int pos);
  void place(int pos, int id) {
    heap_[pos] = id;
    pos_[id] = pos;
  }
  std::vector<int> heap_;    // heap position -> particle
  std::vector<int> pos_;     // particle -> heap position
  std::vector<double> key_;  // particle -> event time
};

}  // namespace granwave
