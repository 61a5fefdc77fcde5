#include "particles/EventQueue.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace granwave {

EventQueue::EventQueue(int particles) { reset(particles); }

void EventQueue::reset(int particles) {
  heap_.resize(particles);
  pos_.resize(particles);
  for (int i = 0; i < particles; ++i) place(i, {std::numeric_limits<double>::infinity(), i});
}

EventQueue::Layout EventQueue::layout() const {
  Layout out;
  out.keys.reserve(heap_.size());
  out.ids.reserve(heap_.size());
  for (const Node& node : heap_) {
    out.keys.push_back(node.key);
    out.ids.push_back(node.id);
  }
  return out;
}

void EventQueue::restore(const Layout& saved) {
  const int n = static_cast<int>(saved.ids.size());
  if (saved.keys.size() != saved.ids.size())
    throw std::invalid_argument("event queue: " + std::to_string(saved.keys.size()) + " keys for " +
                                std::to_string(n) + " particles");
  std::vector<int> pos(n, -1);
  for (int k = 0; k < n; ++k) {
    const int id = saved.ids[k];
    if (id < 0 || id >= n || pos[id] >= 0)
      throw std::invalid_argument("event queue: particle " + std::to_string(id) +
                                  " is out of range or appears twice");
    pos[id] = k;
    if (k > 0 && saved.keys[(k - 1) >> 1] > saved.keys[k])
      throw std::invalid_argument("event queue: the saved keys are not a min-heap");
  }
  heap_.resize(n);
  for (int k = 0; k < n; ++k) heap_[k] = {saved.keys[k], saved.ids[k]};
  pos_ = std::move(pos);
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
