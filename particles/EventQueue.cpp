#include "particles/EventQueue.hpp"

#include <limits>

namespace granwave {

EventQueue::EventQueue(int particles) { reset(particles); }

void EventQueue::reset(int particles) {
  heap_.resize(particles);
  pos_.resize(particles);
  key_.assign(particles, std::numeric_limits<double>::infinity());
  for (int i = 0; i < particles; ++i) place(i, i);
}

void EventQueue::update(int id, double time) {
  const double old = key_[id];
  key_[id] = time;
  if (time < old) {
    siftUp(pos_[id]);
  } else {
    siftDown(pos_[id]);
  }
}

void EventQueue::siftUp(int pos) {
  const int id = heap_[pos];
  const double k = key_[id];
  while (pos > 0) {
    const int parent = (pos - 1) >> 1;
    if (key_[heap_[parent]] <= k) break;
    place(pos, heap_[parent]);
    pos = parent;
  }
  place(pos, id);
}

void EventQueue::siftDown(int pos) {
  const int n = size();
  const int id = heap_[pos];
  const double k = key_[id];
  for (;;) {
    int child = 2 * pos + 1;
    if (child >= n) break;
    if (child + 1 < n && key_[heap_[child + 1]] < key_[heap_[child]]) ++child;
    if (key_[heap_[child]] >= k) break;
    place(pos, heap_[child]);
    pos = child;
  }
  place(pos, id);
}

}  // namespace granwave
