// RadixQueue (common/radix_queue.h) against std::priority_queue: the same keys come out in the same
// order, for the monotone sequences a consistent A* makes and for keys below the last one popped.
#include "common/radix_queue.h"

#include <gtest/gtest.h>

#include <functional>
#include <queue>
#include <random>
#include <vector>

namespace splinekit {
namespace {

using Reference = std::priority_queue<float, std::vector<float>, std::greater<float>>;

TEST(RadixQueue, PopsKeysInOrderLikeABinaryHeap) {
  std::mt19937 rng(3);
  RadixQueue queue;
  Reference reference;
  float last = 0;
  std::uniform_real_distribution<float> step(0.f, 2.f);
  std::uniform_int_distribution<int> pushes(0, 4);
  for (int round = 0; round < 20000; ++round) {
    // A search's pushes: its keys are at least the last popped (a consistent A* term), some equal.
    for (int k = pushes(rng); k > 0; --k) {
      const float key = k == 1 ? last : last + step(rng) * step(rng) * step(rng);
      queue.push(key, round);
      reference.push(key);
    }
    if (reference.empty()) continue;
    ASSERT_FALSE(queue.empty());
    const auto [key, value] = queue.pop();
    ASSERT_EQ(key, reference.top()) << "round " << round;
    reference.pop();
    last = key;
    EXPECT_GE(value, 0);
  }
  EXPECT_EQ(queue.size(), reference.size());
}

TEST(RadixQueue, KeysBelowTheLastPoppedComeFirst) {
  // A weighted (not quite consistent) A* term pushes keys below the last one popped: they must still
  // come out before every larger key, smallest first.
  RadixQueue queue;
  for (float key : {5.f, 9.f, 7.f, 100.f}) queue.push(key, static_cast<int>(key));
  EXPECT_EQ(queue.pop().first, 5.f);
  for (float key : {3.f, 4.5f, 1.f, 6.f}) queue.push(key, static_cast<int>(key));
  std::vector<float> order;
  while (!queue.empty()) order.push_back(queue.pop().first);
  EXPECT_EQ(order, (std::vector<float>{1.f, 3.f, 4.5f, 6.f, 7.f, 9.f, 100.f}));
}

TEST(RadixQueue, ClearForgetsEntriesAndTheLastKey) {
  RadixQueue queue;
  queue.push(10.f, 1);
  queue.push(20.f, 2);
  EXPECT_EQ(queue.pop().second, 1);
  queue.clear();
  EXPECT_TRUE(queue.empty());
  // After clear, small keys are ordinary again (not "below the last").
  queue.push(2.f, 7);
  queue.push(1.f, 8);
  EXPECT_EQ(queue.pop(), (std::pair<float, int>{1.f, 8}));
  EXPECT_EQ(queue.pop(), (std::pair<float, int>{2.f, 7}));
  EXPECT_TRUE(queue.empty());
}

TEST(RadixQueue, ZeroAndLargeKeys) {
  RadixQueue queue;
  for (float key : {0.f, 3.0e38f, 1e-30f, 0.f, 1.f}) queue.push(key, 0);
  std::vector<float> order;
  while (!queue.empty()) order.push_back(queue.pop().first);
  EXPECT_EQ(order, (std::vector<float>{0.f, 0.f, 1e-30f, 1.f, 3.0e38f}));
}

}  // namespace
}  // namespace splinekit
