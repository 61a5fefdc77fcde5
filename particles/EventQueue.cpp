#include "particles/EventQueue.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace granwave {

namespace {

// Buckets per year: a power of two of at least twice the particles, so that the year spans
// about four mean pending times and few entries wait in the overflow (Paul 2007, Sec. 3).
int bucketsFor(int particles) {
  int b = 16;
  while (b < 2 * particles) b *= 2;
  return b;
}

// Entries per bucket near the front that the width aims at.
constexpr double kEntriesPerBucket = 2.0;
// The current bucket's heap may hold this many entries before the width is re-estimated.
constexpr std::size_t kHeapLimit = 64;

}  // namespace

EventQueue::EventQueue(int particles) { reset(particles); }

void EventQueue::reset(int particles) {
  key_.assign(particles, kInfinity);
  where_.assign(particles, kNowhere);
  next_.assign(particles, -1);
  prev_.assign(particles, -1);
  heap_pos_.assign(particles, -1);
  bucket_.assign(bucketsFor(particles), -1);
  heap_.clear();
  overflow_ = -1;
  listed_ = 0;
  origin_ = 0;
  width_ = inverse_width_ = 1;
  current_ = 0;
  year_end_ = static_cast<std::int64_t>(bucket_.size());
  heap_limit_ = kHeapLimit;
}

EventQueue::Layout EventQueue::layout() const {
  Layout out;
  out.keys = key_;
  out.ids.resize(key_.size());
  for (std::size_t i = 0; i < key_.size(); ++i) out.ids[i] = static_cast<int>(i);
  return out;
}

void EventQueue::restore(const Layout& saved) {
  const int n = static_cast<int>(saved.ids.size());
  if (saved.keys.size() != saved.ids.size())
    throw std::invalid_argument("event queue: " + std::to_string(saved.keys.size()) + " keys for " +
                                std::to_string(n) + " particles");
  std::vector<double> keys(n, kInfinity);
  std::vector<char> seen(n, 0);
  for (int k = 0; k < n; ++k) {
    const int id = saved.ids[k];
    if (id < 0 || id >= n || seen[id])
      throw std::invalid_argument("event queue: particle " + std::to_string(id) +
                                  " is out of range or appears twice");
    if (std::isnan(saved.keys[k]))
      throw std::invalid_argument("event queue: particle " + std::to_string(id) +
                                  " has no event time (NaN)");
    seen[id] = 1;
    keys[id] = saved.keys[k];
  }
  reset(n);
  key_ = std::move(keys);
  rebuild();
}

std::int64_t EventQueue::bucketOf(double t) const {
  const double x = (t - origin_) * inverse_width_;
  if (!(x < 4e18)) return std::numeric_limits<std::int64_t>::max();  // far future
  if (x < 0.0) return -1;  // before the origin: at or before the current bucket
  return static_cast<std::int64_t>(x);
}

void EventQueue::update(int id, double time) {
  remove(id);
  insert(id, time);
  if (heap_.size() > heap_limit_) rebuild();  // the width is too large for the times now
}

void EventQueue::insert(int id, double t) {
  key_[id] = t;
  if (t == kInfinity) {
    where_[id] = kNowhere;
    return;
  }
  const std::int64_t k = bucketOf(t);
  if (k <= current_) {
    heapPush(id);
  } else if (k < year_end_) {
    const int b = static_cast<int>(k & static_cast<std::int64_t>(bucket_.size() - 1));
    where_[id] = b;
    link(bucket_[b], id);
    ++listed_;
  } else {
    where_[id] = kInOverflow;
    link(overflow_, id);
  }
}

void EventQueue::remove(int id) {
  const int w = where_[id];
  if (w == kInHeap) {
    heapRemove(id);
  } else if (w == kInOverflow) {
    unlink(overflow_, id);
  } else if (w >= 0) {
    unlink(bucket_[w], id);
    --listed_;
  }
  where_[id] = kNowhere;
}

// The current bucket is empty: heap the next non-empty one of the year, or, when the year
// holds nothing more, start a new year at the earliest pending time.
void EventQueue::advance() {
  while (heap_.empty()) {
    if (listed_ == 0) {
      if (overflow_ >= 0) rebuild();
      return;  // rebuilt with the earliest entry in the heap, or all keys are infinite
    }
    ++current_;
    const int b = static_cast<int>(current_ & static_cast<std::int64_t>(bucket_.size() - 1));
    for (int id = bucket_[b]; id >= 0;) {
      const int next = next_[id];
      heapPush(id);
      --listed_;
      id = next;
    }
    bucket_[b] = -1;
  }
}

// A new year starting at the earliest pending time, with the width re-estimated from the
// pending times: for times spread like an exponential of mean s past the earliest one, n
// entries put n / s per unit time near the front.
void EventQueue::rebuild() {
  double earliest = kInfinity, sum = 0;
  int finite = 0;
  for (const double k : key_) {
    if (k == kInfinity) continue;
    earliest = std::min(earliest, k);
    sum += k;
    ++finite;
  }
  heap_.clear();
  std::fill(bucket_.begin(), bucket_.end(), -1);
  overflow_ = -1;
  listed_ = 0;
  current_ = 0;
  year_end_ = static_cast<std::int64_t>(bucket_.size());
  if (finite == 0) {
    std::fill(where_.begin(), where_.end(), kNowhere);
    return;
  }
  const double spread = sum / finite - earliest;
  const double width = kEntriesPerBucket * spread / finite;
  // All times equal (a lattice start): keep the old width; it only decides the buckets.
  if (width > 1e-300 && std::isfinite(width)) {
    width_ = width;
    inverse_width_ = 1.0 / width;
  }
  origin_ = earliest;
  for (int id = 0; id < size(); ++id) insert(id, key_[id]);
  // Many equal times cannot be split by any width: do not rebuild again until they double.
  heap_limit_ = std::max(kHeapLimit, 2 * heap_.size());
}

void EventQueue::link(int& head, int id) {
  prev_[id] = -1;
  next_[id] = head;
  if (head >= 0) prev_[head] = id;
  head = id;
}

void EventQueue::unlink(int& head, int id) {
  if (prev_[id] >= 0) {
    next_[prev_[id]] = next_[id];
  } else {
    head = next_[id];
  }
  if (next_[id] >= 0) prev_[next_[id]] = prev_[id];
}

void EventQueue::heapPush(int id) {
  where_[id] = kInHeap;
  heap_.push_back({key_[id], id});
  siftUp(static_cast<int>(heap_.size()) - 1, heap_.back());
}

void EventQueue::heapRemove(int id) {
  const int pos = heap_pos_[id];
  const Node last = heap_.back();
  heap_.pop_back();
  if (pos == static_cast<int>(heap_.size())) return;  // it was the last node
  if (pos > 0 && before(last, heap_[(pos - 1) >> 1])) {
    siftUp(pos, last);
  } else {
    siftDown(pos, last);
  }
}

void EventQueue::siftUp(int pos, Node node) {
  while (pos > 0) {
    const int parent = (pos - 1) >> 1;
    if (!before(node, heap_[parent])) break;
    place(pos, heap_[parent]);
    pos = parent;
  }
  place(pos, node);
}

void EventQueue::siftDown(int pos, Node node) {
  const int n = static_cast<int>(heap_.size());
  for (;;) {
    int child = 2 * pos + 1;
    if (child >= n) break;
    if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
    if (!before(heap_[child], node)) break;
    place(pos, heap_[child]);
    pos = child;
  }
  place(pos, node);
}

}  // namespace granwave
