#include "morph/correspondence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "test_shapes.h"

using namespace splinekit;
using namespace splinekit::morph;

namespace {

ChainMeasure random_measure(std::mt19937& rng, int segments, bool closed) {
  std::uniform_real_distribution<double> len(0.05, 1.0), ang(-1.5, 1.5);
  ChainMeasure m;
  for (int k = 0; k < segments; ++k) {
    m.length.push_back(len(rng));
    m.bending.push_back(ang(rng));
    m.middle.push_back(ang(rng));
    m.middle.push_back(ang(rng));
  }
  const int anchors = closed ? segments : segments + 1;
  for (int a = 0; a < anchors; ++a) {
    m.kink.push_back((!closed && (a == 0 || a == segments)) ? 0.0 : ang(rng));
    m.anchor.push_back(ang(rng));
    m.anchor.push_back(ang(rng));
  }
  return m;
}

// Every monotone path from (0,0) to (m,n), by recursion.
void all_paths(int m, int n, std::vector<Move>& path, const std::function<void(const std::vector<Move>&)>& visit,
               int i = 0, int j = 0) {
  if (i == m && j == n) return visit(path);
  const Move moves[3] = {Move::kBoth, Move::kFirst, Move::kSecond};
  for (Move mv : moves) {
    const int i2 = i + (mv != Move::kSecond), j2 = j + (mv != Move::kFirst);
    if (i2 > m || j2 > n) continue;
    path.push_back(mv);
    all_paths(m, n, path, visit, i2, j2);
    path.pop_back();
  }
}

ChainMeasure reversed_measure(const ChainMeasure& m, bool closed) {
  ChainMeasure r;
  const int n = int(m.length.size()), a = int(m.kink.size());
  for (int k = n - 1; k >= 0; --k) {
    r.length.push_back(m.length[k]);
    r.bending.push_back(-m.bending[k]);
    r.middle.push_back(m.middle[2 * k]);
    r.middle.push_back(m.middle[2 * k + 1]);
  }
  for (int i = 0; i < a; ++i) {
    const int j = reversed_anchor(i, a, closed);
    r.kink.push_back(-m.kink[size_t(j)]);
    r.anchor.push_back(m.anchor[2 * size_t(j)]);
    r.anchor.push_back(m.anchor[2 * size_t(j) + 1]);
  }
  return r;
}

}  // namespace

TEST(MorphCorrespondence, IdenticalChainsCostNothingAlongTheDiagonal) {
  std::mt19937 rng(7);
  for (bool closed : {false, true}) {
    const ChainMeasure a = random_measure(rng, 6, closed);
    CorrespondenceSearch s;
    const Correspondence c = s.search(a, a, reversed_measure(a, closed), closed, {}, {}, CorrespondenceSearch::kBoth);
    EXPECT_EQ(c.work, 0.0);
    EXPECT_EQ(c.start, 0);
    EXPECT_FALSE(c.reversed);
    EXPECT_EQ(c.moves, std::vector<Move>(6, Move::kBoth));
  }
}

TEST(MorphCorrespondence, SearchEqualsBruteForceOverEveryPath) {
  std::mt19937 rng(42);
  WorkOptions o;
  o.kink_exponent = 1.5;
  for (int trial = 0; trial < 30; ++trial) {
    const bool closed = trial % 2 == 1;
    const int m = 1 + trial % 4, n = 1 + (trial / 4) % 4;
    const ChainMeasure a = random_measure(rng, m, closed), b = random_measure(rng, n, closed);
    double brute = std::numeric_limits<double>::infinity();
    std::vector<Move> path;
    for (int start = 0; start < (closed ? n : 1); ++start) {
      all_paths(m, n, path,
                [&](const std::vector<Move>& p) { brute = std::min(brute, path_work(a, b, closed, start, p, o)); });
    }
    CorrespondenceSearch s;
    const Correspondence c = s.search(a, b, reversed_measure(b, closed), closed, {}, o, CorrespondenceSearch::kForward);
    EXPECT_NEAR(c.work, brute, 1e-12 * (1 + brute)) << "trial " << trial;
    EXPECT_NEAR(path_work(a, b, closed, c.start, c.moves, o), c.work, 1e-12 * (1 + brute));
  }
}

TEST(MorphCorrespondence, BothDirectionsGiveTheSameWork) {
  std::mt19937 rng(3);
  for (bool closed : {false, true}) {
    const ChainMeasure a = random_measure(rng, 5, closed), b = random_measure(rng, 7, closed);
    const ChainMeasure rb = reversed_measure(b, closed);
    CorrespondenceSearch s;
    const Correspondence forward = s.search(a, b, rb, closed, {}, {}, CorrespondenceSearch::kBoth);
    const Correspondence backward = s.search(a, rb, b, closed, {}, {}, CorrespondenceSearch::kBoth);
    EXPECT_NEAR(forward.work, backward.work, 1e-12);
    EXPECT_NE(forward.reversed, backward.reversed);
  }
}

TEST(MorphCorrespondence, PinsArePassedThroughAndCostAtLeastTheFreeOptimum) {
  std::mt19937 rng(11);
  const ChainMeasure a = random_measure(rng, 6, true), b = random_measure(rng, 6, true);
  CorrespondenceSearch s;
  const Correspondence free = s.search(a, b, reversed_measure(b, true), true, {}, {}, CorrespondenceSearch::kForward);
  const std::vector<AnchorPin> pins = {{0, 3}, {2, 4}};
  const Correspondence pinned =
      s.search(a, b, reversed_measure(b, true), true, pins, {}, CorrespondenceSearch::kForward);
  ASSERT_TRUE(std::isfinite(pinned.work));
  EXPECT_GE(pinned.work, free.work - 1e-12);
  EXPECT_EQ(pinned.start, 3);  // A's anchor 0 is pinned to B's anchor 3
  int i = 0, j = 0;
  bool met = false;
  for (Move mv : pinned.moves) {
    i += mv != Move::kSecond;
    j += mv != Move::kFirst;
    if (i == 2 && (j + pinned.start) % 6 == 4) met = true;
  }
  EXPECT_TRUE(met);
  // Crossing pins cannot be met: +inf.
  const Correspondence crossed = s.search(a, b, reversed_measure(b, true), true, {{0, 0}, {2, 4}, {3, 2}}, {}, false);
  EXPECT_FALSE(std::isfinite(crossed.work));
}

TEST(MorphCorrespondence, DivideAndConquerOverStartsEqualsEveryStartSearchedAlone) {
  // The search relaxes each start only between the paths of the starts around it; on random
  // closed chains its optimum equals the least of every start solved over the whole grid.
  std::mt19937 rng(5);
  WorkOptions o;
  for (int trial = 0; trial < 12; ++trial) {
    const int m = 8 + 5 * trial % 23, n = 6 + 7 * trial % 29;
    const ChainMeasure a = random_measure(rng, m, true), b = random_measure(rng, n, true);
    CorrespondenceSearch s;
    double each = std::numeric_limits<double>::infinity();
    for (int start = 0; start < n; ++start) each = std::min(each, s.solve_start(a, b, true, start, {}, o, nullptr));
    CorrespondenceSearch d;
    const Correspondence c = d.search(a, b, reversed_measure(b, true), true, {}, o, CorrespondenceSearch::kForward);
    EXPECT_NEAR(c.work, each, 1e-9 * each) << "trial " << trial << " (" << m << " x " << n << ")";
    EXPECT_NEAR(path_work(a, b, true, c.start, c.moves, o), c.work, 1e-9 * each);
    EXPECT_LT(d.counters().cells, int64_t(n) * (m + 1) * (n + 1));  // fewer cells than start by start
  }
}
