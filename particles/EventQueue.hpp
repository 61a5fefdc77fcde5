#pragma once
// Future-event list: one entry per particle, keyed by that particle's next event time, in a
// calendar (bucket) queue with O(1) insertion and removal (R. Brown, Commun. ACM 31, 1220
// (1988); G. Paul, J. Comput. Phys. 221, 615 (2007)). Updating a particle's time moves its
// entry; there are never stale entries, only stale events (see Event.hpp).
//
// Time is cut into buckets of equal width starting at an origin; bucket k holds the times in
// [origin + k w, origin + (k + 1) w). Only the current bucket is ordered (a small binary heap);
// the next B - 1 buckets ("the year", B a power of two >= N) are unordered doubly linked
// lists, later times wait in an unordered overflow list and infinite times in none. When the
// current bucket runs empty the next non-empty one is heaped; when the year ends the overflow
// is spread over the next one. The width is chosen so that about two entries fall into a
// bucket near the front (from the spread of the pending times, re-estimated every year), so
// a particle's update costs a few list operations instead of a sift through log2 N levels.
//
// Order: by time, and between equal times by particle index. That order is a function of
// the keys alone, not of the queue's history or its width, so a queue rebuilt from the keys
// (a restored checkpoint) pops exactly as the original would.
#include <cstdint>
#include <vector>

namespace granwave {

class EventQueue {
 public:
  explicit EventQueue(int particles = 0);
  void reset(int particles);  // all keys +inf

  // The earliest entry (the lowest index among equal times). Not const: finding it may
  // advance the calendar to the next non-empty bucket.
  int top() {
    if (heap_.empty()) advance();
    return heap_.empty() ? 0 : heap_[0].id;  // all keys infinite: index 0 comes first
  }
  double topTime() {
    if (heap_.empty()) advance();
    return heap_.empty() ? kInfinity : heap_[0].key;
  }
  double time(int id) const { return key_[id]; }
  // The entries that follow the earliest in the current bucket's heap (its children: one of
  // them is next unless an update comes before): the particle at slot k = 1, 2, or -1.
  int follower(int k) const { return k < static_cast<int>(heap_.size()) ? heap_[k].id : -1; }
  void update(int id, double time);
  int size() const { return static_cast<int>(key_.size()); }

  // The keys (checkpoints); ids[k] is the particle of keys[k]. Any order restores the same
  // queue, because the order of events is a function of the keys (see above).
  struct Layout {
    std::vector<double> keys;
    std::vector<int> ids;
  };
  Layout layout() const;
  // std::invalid_argument unless `saved` holds each of 0..n-1 once, with no NaN key.
  void restore(const Layout& saved);

 private:
  static constexpr double kInfinity = __builtin_huge_val();
  // Where an entry lives: a bucket list (>= 0) or one of these.
  static constexpr int kInHeap = -1, kInOverflow = -2, kNowhere = -3;
  struct Node {
    double key;
    int id;
  };
  static bool before(const Node& a, const Node& b) {
    return a.key < b.key || (a.key == b.key && a.id < b.id);
  }

  std::int64_t bucketOf(double t) const;
  void insert(int id, double t);
  void remove(int id);
  void advance();
  void rebuild();
  // lists (buckets and overflow)
  void link(int& head, int id);
  void unlink(int& head, int id);
  int& headOf(int where) { return where == kInOverflow ? overflow_ : bucket_[where]; }
  // the current bucket's heap
  void heapPush(int id);
  void heapRemove(int id);
  void siftUp(int pos, Node node);
  void siftDown(int pos, Node node);
  void place(int pos, Node node) {
    heap_[pos] = node;
    heap_pos_[node.id] = pos;
  }

  std::vector<double> key_;  // particle -> time
  std::vector<int> where_;   // particle -> bucket, kInHeap, kInOverflow or kNowhere
  std::vector<int> next_, prev_, heap_pos_;
  std::vector<int> bucket_;  // bucket -> first particle, -1 if empty
  std::vector<Node> heap_;   // the current bucket, ordered
  int overflow_ = -1;        // first particle beyond the year
  int listed_ = 0;           // entries in bucket lists
  double origin_ = 0, width_ = 1, inverse_width_ = 1;
  std::int64_t current_ = 0, year_end_ = 0;  // current bucket; first bucket after the year
  std::size_t heap_limit_ = 0;               // a larger current bucket re-estimates the width
};

}  // namespace granwave
