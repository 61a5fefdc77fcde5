#pragma once
// Future-event list: an indexed binary min-heap holding exactly one entry per particle,
// keyed by that particle's next event time. Updating a particle's time re-sifts its entry
// (O(log N)); there are never stale heap entries, only stale events (see Event.hpp).
// Keys are stored inside the heap nodes, so sifting reads contiguous memory (the key lookup
// through a second array was a quarter of the cache misses at N = 10^5). A processed
// particle's new event usually belongs near the bottom, so sifting down is bottom-up
// (Floyd): the hole goes to a leaf along the smaller children, one comparison per level and
// no branch on the new key, then the key sifts up the few levels it must.
#include <cstdint>
#include <vector>

namespace granwave {

class EventQueue {
 public:
  explicit EventQueue(int particles = 0);
  void reset(int particles);  // all keys +inf

  int top() const { return heap_[0].id; }
  double topTime() const { return heap_[0].key; }
  double time(int id) const { return heap_[pos_[id]].key; }
  void update(int id, double time);
  int size() const { return static_cast<int>(heap_.size()); }

  // The heap exactly as stored, in heap order (checkpoints): events at equal times leave it
  // in the order this layout gives, so a restored run only continues bit-identically from the
  // same layout, not from a heap rebuilt from the keys.
  struct Layout {
    std::vector<double> keys;
    std::vector<int> ids;
  };
  Layout layout() const;
  // std::invalid_argument unless `saved` is a min-heap holding each of 0..n-1 once.
  void restore(const Layout& saved);

 private:
  struct Node {
    double key;
    int id;
  };
  void siftUp(int pos, Node node);
  void siftDown(int pos, Node node);
  void place(int pos, Node node) {
    heap_[pos] = node;
    pos_[node.id] = pos;
  }
  std::vector<Node> heap_;  // heap position -> (time, particle)
  std::vector<int> pos_;    // particle -> heap position
};

}  // namespace granwave
