// splinekit — a priority queue for label-setting searches (Dijkstra, A*): a radix heap on
// non-negative float keys (Ahuja, Mehlhorn, Orlin & Tarjan, "Faster algorithms for the shortest path
// problem", J. ACM 37(2), 1990; here on the keys' bit patterns, which order non-negative floats as
// their values do).
//
// A search whose heuristic is consistent pops non-decreasing keys, and every key it pushes is at
// least the last one popped. Entries are then kept in 33 buckets by the highest bit in which their
// key differs from the last key popped; a pop takes from bucket 0 (keys equal to the last) or, when
// it is empty, spreads the lowest non-empty bucket around its smallest key. Each entry moves down
// at most 32 times and no comparison tree is kept, so on the large refined-graph searches of the
// surface solver (a million entries) a pop costs a fraction of a binary heap's sift-down, which
// missed the cache on every level.
//
// Keys below the last one popped (a weighted, not quite consistent A* term) go to a small binary
// heap that pops first, so the queue always returns its smallest key. Equal keys come out in no
// particular order.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace splinekit {

class RadixQueue {
 public:
  // ---- Queries ----
  bool empty() const { return size_ == 0 && below_.empty(); }
  size_t size() const { return size_ + below_.size(); }

  // ---- Mutators ----
  // Empties the queue (keeping its storage) and forgets the last key popped.
  void clear() {
    for (auto& bucket : buckets_) bucket.clear();
    below_.clear();
    size_ = 0;
    last_ = 0;
  }
  // Adds `value` with `key` (>= 0, not NaN).
  void push(float key, int value) {
    const uint32_t k = bits(key);
    if (k < last_) {
      below_.push_back({k, value});
      std::push_heap(below_.begin(), below_.end(), Greater{});
      return;
    }
    buckets_[bucket_of(k)].push_back({k, value});
    ++size_;
  }
  // Removes an entry of the smallest key: (key, value). The queue must not be empty.
  std::pair<float, int> pop() {
    if (!below_.empty()) {
      std::pop_heap(below_.begin(), below_.end(), Greater{});
      const Item top = below_.back();
      below_.pop_back();
      return {value_of(top.key), top.value};
    }
    if (buckets_[0].empty()) {
      int b = 1;
      while (buckets_[b].empty()) ++b;
      std::vector<Item>& from = buckets_[b];
      uint32_t least = from[0].key;
      for (const Item& item : from) least = std::min(least, item.key);
      last_ = least;
      for (const Item& item : from) buckets_[bucket_of(item.key)].push_back(item);  // all below b
      from.clear();
    }
    const Item top = buckets_[0].back();
    buckets_[0].pop_back();
    --size_;
    return {value_of(top.key), top.value};
  }

 private:
  struct Item {
    uint32_t key;
    int value;
  };
  struct Greater {
    bool operator()(const Item& a, const Item& b) const { return a.key > b.key; }
  };
  static uint32_t bits(float key) {
    uint32_t k;
    std::memcpy(&k, &key, sizeof k);
    return k;
  }
  static float value_of(uint32_t k) {
    float key;
    std::memcpy(&key, &k, sizeof key);
    return key;
  }
  // 0 for the last key popped, else 1 + the highest bit where k differs from it.
  int bucket_of(uint32_t k) const { return k == last_ ? 0 : 32 - __builtin_clz(k ^ last_); }

  std::array<std::vector<Item>, 33> buckets_;
  std::vector<Item> below_;  // keys below last_, a binary min-heap
  size_t size_ = 0;          // entries in the buckets
  uint32_t last_ = 0;        // bit pattern of the last key the buckets gave out
};

}  // namespace splinekit
