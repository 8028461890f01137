#include "morph/chain.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/bezier.h"
#include "test_shapes.h"

using namespace splinekit;
using namespace splinekit::morph;

namespace {

// Max distance from the points of `chain` sampled densely to the curve (x(t) sampled 2000 times per
// segment) of the original points.
double sample_distance(const KnotChain& chain, const std::vector<double>& original, bool closed) {
  std::vector<Vec2> dense;
  const int count = int(original.size() / 2);
  double seg[8];
  for (int k = 0; k < spline_segment_count(count, closed); ++k) {
    spline_segment(original.data(), count, closed, k, seg);
    for (int i = 0; i <= 2000; ++i) dense.push_back(bezier_point(seg, i / 2000.0));
  }
  double worst = 0;
  for (int k = 0; k < chain.segments(); ++k) {
    for (int i = 0; i < 4; ++i) {
      const int p = chain.point_index(k, i);
      seg[2 * i] = chain.points[2 * p];
      seg[2 * i + 1] = chain.points[2 * p + 1];
    }
    for (int i = 0; i <= 10; ++i) {
      const Vec2 q = bezier_point(seg, i / 10.0);
      double best = 1e300;
      for (const Vec2& d : dense) best = std::min(best, (d - q).norm());
      worst = std::max(worst, best);
    }
  }
  return worst;
}

}  // namespace

TEST(MorphChain, SmoothJoinGetsDoubleKnotWithHandleRatio) {
  // Two segments through (1,0) with collinear handles of lengths 1 and 2: C1 in B-spline form
  // needs knot intervals in ratio 2 : 1 (|H_out − P| / |P − H_in| = Δr / Δl).
  const std::vector<double> p = {-3, 0, -2, 1, 0, 0, 1, 0, 3, 0, 4, 1, 5, 0};
  KnotChain c;
  ASSERT_EQ(chain_from_bezier(p.data(), 7, false, {}, c), "");
  ASSERT_EQ(c.anchors(), 3);
  EXPECT_EQ(c.smooth[1], 1);
  EXPECT_EQ(c.smooth[0], 0);
  EXPECT_EQ(c.smooth[2], 0);
  EXPECT_NEAR(c.knots[1] / c.knots[0], 2.0, 1e-12);
  EXPECT_NEAR(c.knots[0] + c.knots[1], 1.0, 1e-12);
}

TEST(MorphChain, CornerGetsTripleKnotAndArcLengthIntervals) {
  const auto sq = test::polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  KnotChain c;
  ASSERT_EQ(chain_from_bezier(sq.data(), 12, true, {}, c), "");
  for (int a = 0; a < 4; ++a) EXPECT_EQ(c.smooth[a], 0);
  // Intervals proportional to the side lengths 2, 1, 2, 1 over a perimeter of 6.
  EXPECT_NEAR(c.knots[0], 2.0 / 6, 1e-9);
  EXPECT_NEAR(c.knots[1], 1.0 / 6, 1e-9);
}

TEST(MorphChain, ClosedChainStartsAtACorner) {
  const auto d = test::d_shape();  // anchors: (0,-1) corner, (1,0) smooth, (0,1) corner
  const auto rotated_pts = std::vector<double>(d.begin() + 6, d.end());
  std::vector<double> p = rotated_pts;
  p.insert(p.end(), d.begin(), d.begin() + 6);  // now starts at the smooth anchor (1,0)
  KnotChain c;
  ASSERT_EQ(chain_from_bezier(p.data(), 9, true, {}, c), "");
  EXPECT_EQ(c.smooth[0], 0);
  EXPECT_EQ(c.smooth[2] + c.smooth[1], 1);
  EXPECT_LT(sample_distance(c, p, true), 1e-9);
}

TEST(MorphChain, LengthLimitSplitsWithoutChangingTheCurve) {
  const auto circle = test::circle(0, 0, 10, 4);  // perimeter ≈ 62.8, arcs ≈ 15.7
  KnotChain c;
  ChainOptions o;
  o.max_length = 2.0;
  ASSERT_EQ(chain_from_bezier(circle.data(), 12, true, o, c), "");
  EXPECT_EQ(c.segments(), 4 * 8);                                        // ceil(15.7 / 2) = 8 pieces per arc
  for (int a = 0; a < c.anchors(); ++a) EXPECT_EQ(c.smooth[a], 1) << a;  // all joins stay C1
  EXPECT_LT(sample_distance(c, circle, true), 1e-9);
  double sum = 0;
  for (double k : c.knots) sum += k;
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(MorphChain, ReverseTwiceAndRotateAreIdentities) {
  const auto d = test::d_shape(3);
  KnotChain c;
  ASSERT_EQ(chain_from_bezier(d.data(), 9, true, {}, c), "");
  const KnotChain rr = reversed(reversed(c));
  EXPECT_EQ(rr.points, c.points);
  EXPECT_EQ(rr.knots, c.knots);
  EXPECT_EQ(rr.smooth, c.smooth);
  const KnotChain r = reversed(c);
  EXPECT_EQ(r.points[0], c.points[0]);
  EXPECT_EQ(r.knots[0], c.knots[2]);
  const KnotChain full = rotated(rotated(c, 1), 2);
  EXPECT_EQ(full.points, c.points);
}

TEST(MorphChain, BadInputIsNamed) {
  KnotChain c;
  const std::vector<double> one = {0, 0};
  EXPECT_NE(chain_from_bezier(one.data(), 1, false, {}, c), "");
  const std::vector<double> same = {1, 1, 1, 1, 1, 1, 1, 1};
  EXPECT_NE(chain_from_bezier(same.data(), 4, false, {}, c).find("zero length"), std::string::npos);
  const std::vector<double> nan = {0, 0, NAN, 1, 2, 2, 3, 3};
  EXPECT_NE(chain_from_bezier(nan.data(), 4, false, {}, c).find("non-finite"), std::string::npos);
}
