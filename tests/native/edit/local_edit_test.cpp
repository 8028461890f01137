// One localized drag: the invariants of §3.1, §3.3 and §3.4.
#include "edit/local_edit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "test_curves.h"

using namespace splinekit;
using namespace splinekit::edit;

namespace {

CatmullRom make(const std::vector<double>& xy, bool closed, Parameterization p = Parameterization::kCentripetal) {
  CatmullRom c;
  EXPECT_EQ(c.set(xy.data(), int(xy.size() / 2), closed, p), "");
  return c;
}

EditOptions window(int left, int right, Falloff kind = Falloff::kCosine, bool normals = false) {
  EditOptions o;
  o.left = left;
  o.right = right;
  o.falloff.kind = kind;
  o.normals = normals;
  return o;
}

bool in_window(const LocalEdit& e, int i) {
  for (int k : e.indices())
    if (k == i) return true;
  return false;
}

}  // namespace

TEST(LocalEdit, WindowOfZeroIsAPlainControlPointMove) {
  const CatmullRom c = make(edit_test::wave(20), false);
  LocalEdit e;
  ASSERT_EQ(e.begin(c, 7, window(0, 0)), "");
  e.move(1.5, -2.25);
  std::vector<double> expected = c.points();
  expected[14] += 1.5;
  expected[15] += -2.25;
  EXPECT_EQ(e.points(), expected);
  // A window of one on each side is the same: its ends do not move.
  ASSERT_EQ(e.begin(c, 7, window(1, 1)), "");
  e.move(1.5, -2.25);
  EXPECT_EQ(e.points(), expected);
}

TEST(LocalEdit, DraggedPointMovesByExactlyTheDisplacement) {
  for (bool normals : {false, true}) {
    for (Falloff kind : {Falloff::kLinear, Falloff::kGaussian, Falloff::kCosine}) {
      const CatmullRom c = make(edit_test::wave(30), false);
      LocalEdit e;
      ASSERT_EQ(e.begin(c, 12, window(6, 9, kind, normals)), "");
      const double dx = 0.1 + 0.2, dy = -1.0 / 3.0;
      e.move(dx, dy);
      EXPECT_EQ(e.points()[24], c.points()[24] + dx);
      EXPECT_EQ(e.points()[25], c.points()[25] + dy);
    }
  }
}

TEST(LocalEdit, PointsOutsideTheWindowAndItsEndsAreBitIdentical) {
  for (bool closed : {false, true}) {
    for (bool normals : {false, true}) {
      const CatmullRom c = make(closed ? edit_test::loop(40) : edit_test::wave(40), closed);
      LocalEdit e;
      ASSERT_EQ(e.begin(c, closed ? 2 : 20, window(5, 7, Falloff::kGaussian, normals)), "");
      e.move(3.7, 1.9);
      int moved = 0;
      const int first = e.indices().front(), last = e.indices().back();
      for (int i = 0; i < c.count(); ++i) {
        const bool same = std::memcmp(&e.points()[2 * size_t(i)], &c.points()[2 * size_t(i)], 2 * sizeof(double)) == 0;
        if (!in_window(e, i) || i == first || i == last) {
          EXPECT_TRUE(same) << "point " << i << " closed " << closed;
        } else {
          EXPECT_FALSE(same) << "point " << i << " inside the window did not move";
          ++moved;
        }
      }
      EXPECT_EQ(moved, 11);  // 5 + 7 + 1 minus the two ends
    }
  }
}

TEST(LocalEdit, WithoutNormalsEveryDisplacementIsParallelToTheDragAndScaledByTheFalloff) {
  const CatmullRom c = make(edit_test::wave(50), false);
  LocalEdit e;
  EditOptions o = window(10, 15, Falloff::kCosine);
  o.falloff.alpha = 2.0;
  ASSERT_EQ(e.begin(c, 25, o), "");
  const Vec2 d(2.0, -0.7);
  e.move(d.x(), d.y());
  for (size_t k = 0; k < e.indices().size(); ++k) {
    const int i = e.indices()[k];
    const Vec2 moved = vec2_at(e.points().data(), i) - c.control_point(i);
    EXPECT_NEAR(cross(moved, d), 0.0, 1e-13 * d.squaredNorm()) << i;
    EXPECT_GE(moved.dot(d), 0.0);
    EXPECT_NEAR(moved.norm(), e.weights()[k] * d.norm(), 1e-13 * d.norm());
  }
}

TEST(LocalEdit, WeightsFollowArcLengthAndAreMonotoneOnEachSide) {
  const CatmullRom c = make(edit_test::wave(40), false);
  LocalEdit e;
  ASSERT_EQ(e.begin(c, 20, window(8, 12, Falloff::kLinear)), "");
  const auto& w = e.weights();
  const int center = e.window().left;
  EXPECT_EQ(w[size_t(center)], 1.0);
  EXPECT_EQ(w.front(), 0.0);
  EXPECT_EQ(w.back(), 0.0);
  for (int k = 0; k < center; ++k) EXPECT_LT(w[size_t(k)], w[size_t(k) + 1]);
  for (size_t k = size_t(center); k + 1 < w.size(); ++k) EXPECT_GT(w[k], w[k + 1]);
  // Linear: 1 - d / W with d, W summed from the segments' arc lengths.
  double d = 0, total = 0;
  for (int s = 20; s < 32; ++s) total += c.segment_length(s);
  for (int s = 20; s < 23; ++s) d += c.segment_length(s);
  EXPECT_NEAR(w[size_t(center + 3)], 1.0 - d / total, 1e-12);
}

TEST(LocalEdit, ADragIsStable) {
  // Weights are fixed at begin(): any path of moves ending at D gives the curve of move(D).
  const CatmullRom c = make(edit_test::loop(30), true);
  for (bool normals : {false, true}) {
    LocalEdit a, b;
    ASSERT_EQ(a.begin(c, 4, window(6, 6, Falloff::kCosine, normals)), "");
    ASSERT_EQ(b.begin(c, 4, window(6, 6, Falloff::kCosine, normals)), "");
    a.move(5, 5);
    a.move(-3, 2);
    a.move(1, 2);
    b.move(1, 2);
    EXPECT_EQ(a.points(), b.points());
  }
}

TEST(LocalEdit, NormalsTurnTheDirectionTowardsTheWindowEndsNormals) {
  // A straight horizontal line, dragged sideways along itself at the middle: with normals the
  // points near the window's ends move mostly across the line (along ±y), without they do not.
  std::vector<double> xy;
  for (int i = 0; i < 21; ++i) xy.insert(xy.end(), {double(i), 0.0});
  const CatmullRom c = make(xy, false);
  LocalEdit e;
  ASSERT_EQ(e.begin(c, 10, window(10, 10, Falloff::kLinear, true)), "");
  const Vec2 d(1.0, 0.2);
  e.move(d.x(), d.y());
  // Point 18 (u = 0.8): direction = D̂ turned 80% of the way to +y (the normal on D's side).
  const Vec2 moved = vec2_at(e.points().data(), 18) - c.control_point(18);
  const double from = std::atan2(d.y(), d.x()), to = kPi / 2;
  const double expected_angle = from + 0.8 * (to - from);
  EXPECT_NEAR(std::atan2(moved.y(), moved.x()), expected_angle, 1e-9);
  EXPECT_NEAR(moved.norm(), 0.2 * d.norm(), 1e-9);
  // Dragged along the normal itself: the same as without normals.
  LocalEdit plain;
  ASSERT_EQ(plain.begin(c, 10, window(10, 10, Falloff::kLinear, false)), "");
  e.move(0.0, -2.0);
  plain.move(0.0, -2.0);
  for (int i = 0; i < c.count(); ++i)
    EXPECT_LT((vec2_at(e.points().data(), i) - vec2_at(plain.points().data(), i)).norm(), 1e-12);
  // No displacement: nothing moves.
  e.move(0.0, 0.0);
  EXPECT_EQ(e.points(), c.points());
}

TEST(LocalEdit, WholeClosedLoop) {
  const CatmullRom c = make(edit_test::loop(12), true);
  LocalEdit e;
  ASSERT_EQ(e.begin(c, 0, window(100, 100)), "");
  EXPECT_EQ(e.window().size(), 13);
  e.move(1.0, 1.0);
  // Only the opposite point (both ends) stays.
  int still = 0;
  for (int i = 0; i < c.count(); ++i) still += vec2_at(e.points().data(), i) == c.control_point(i);
  EXPECT_EQ(still, 1);
  EXPECT_EQ(vec2_at(e.points().data(), 6), c.control_point(6));
  EXPECT_EQ(vec2_at(e.points().data(), 0), c.control_point(0) + Vec2(1, 1));
}

TEST(LocalEdit, RejectsBadRequests) {
  const CatmullRom c = make(edit_test::wave(10), false);
  LocalEdit e;
  EXPECT_NE(e.begin(c, 10, window(2, 2)).find("control point 10 is out of range"), std::string::npos);
  EditOptions o = window(2, 2);
  o.falloff.alpha = 0.0;
  EXPECT_NE(e.begin(c, 3, o).find("alpha"), std::string::npos);
  o.falloff.alpha = std::nan("");
  EXPECT_NE(e.begin(c, 3, o).find("alpha"), std::string::npos);
  EXPECT_FALSE(e.active());
}

TEST(LocalEdit, NormalsOverALongWindowMatchTheSlerpFormulaAtEveryPoint) {
  // move() carries the rotation along by small steps; every point must still sit where
  // P⁰ + |D| S(u) slerp(D̂, N̂, u) puts it.
  const CatmullRom c = make(edit_test::wave(3000), false);
  LocalEdit e;
  ASSERT_EQ(e.begin(c, 1200, window(5000, 5000, Falloff::kCosine, true)), "");
  const Vec2 d(-2.5, 4.0), unit = d.normalized();
  e.move(d.x(), d.y());
  const int center = e.window().left;
  double worst = 0;
  for (size_t k = 0; k < e.indices().size(); ++k) {
    const int i = e.indices()[k];
    Vec2 n = int(k) < center ? e.left_normal() : e.right_normal();
    if (n.dot(unit) < 0) n = -n;
    const Vec2 expected = c.control_point(i) + d.norm() * e.weights()[k] * slerp(unit, n, e.distances()[k]);
    worst = std::max(worst, (vec2_at(e.points().data(), i) - expected).norm());
  }
  EXPECT_LT(worst, 1e-12 * d.norm());
  EXPECT_EQ(e.window().size(), 3000);
}
