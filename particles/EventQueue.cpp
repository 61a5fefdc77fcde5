#include "particles/EventQueue.hpp"

#include <limits>

namespace granwave {

EventQueue::EventQueue(int particles) { reset(particles); }

void EventQueue::reset(int particles) {
  heap_.resize(particles);
  pos_.resize(particles);
  for (int i = 0; i < particles; ++i) place(i, {std::numeric_limits<double>::infinity(), i});
}

void EventQueue::update(int id, double time) {
  const int pos = pos_[id];
  const double old = heap_[pos].key;
  if (time < old) {
    siftUp(pos, {time, id});
  } else {
    siftDown(pos, {time, id});
  }
}

void EventQueue::siftUp(int pos, Node node) {
  while (pos > 0) {
    const int parent = (pos - 1) >> 1;
    if (heap_[parent].key <= node.key) break;
    place(pos, heap_[parent]);
    pos = parent;
  }
  place(pos, node);
}

void EventQueue::siftDown(int pos, Node node) {
  const int n = size();
  // Move the hole to a leaf along the smaller children...
  for (;;) {
    int child = 2 * pos + 1;
    if (child >= n) break;
    if (child + 1 < n && heap_[child + 1].key < heap_[child].key) ++child;
    place(pos, heap_[child]);
    pos = child;
  }
  // ...then bring the key back up to where it belongs.
  siftUp(pos, node);
}

}  // namespace granwave
