// Catmull-Rom curves: interpolation, the exact Bézier form against the Barry–Goldman pyramid,
// closed forms of the uniform tangents, continuity tags, cusps, tangent overrides, bad input.
#include "edit/catmull_rom.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/bezier.h"
#include "test_curves.h"

using namespace splinekit;
using namespace splinekit::edit;

namespace {

const Parameterization kAll[3] = {Parameterization::kUniform, Parameterization::kCentripetal,
                                  Parameterization::kChordal};

CatmullRom make(const std::vector<double>& xy, bool closed, Parameterization p) {
  CatmullRom c;
  EXPECT_EQ(c.set(xy.data(), int(xy.size() / 2), closed, p), "");
  return c;
}

// The smallest component of B'(u) along the chord of segment s: negative when the segment
// doubles back on itself (a cusp or a loop).
double min_forward_speed(const CatmullRom& c, int s) {
  const Vec2 chord = c.control_point(s + 1) - c.control_point(s);
  double worst = 1e300;
  for (int k = 0; k <= 1000; ++k) worst = std::min(worst, c.derivative(s, k / 1000.0).dot(chord));
  return worst;
}

}  // namespace

TEST(CatmullRom, InterpolatesEveryControlPoint) {
  for (bool closed : {false, true}) {
    for (Parameterization p : kAll) {
      const std::vector<double> xy = closed ? edit_test::loop(13) : edit_test::wave(17);
      const CatmullRom c = make(xy, closed, p);
      for (int s = 0; s < c.segment_count(); ++s) {
        const double tol = 1e-12 * c.size();
        EXPECT_LT((c.point(s, 0.0) - c.control_point(s)).norm(), tol) << s;
        EXPECT_LT((c.point(s, 1.0) - c.control_point(s + 1)).norm(), tol) << s;
      }
      // Open: the curve starts and ends at the end points; closed: the last segment returns to P_0.
      EXPECT_LT(
          (c.point(c.segment_count() - 1, 1.0) - (closed ? c.control_point(0) : c.control_point(c.count() - 1))).norm(),
          1e-12 * c.size());
    }
  }
}

TEST(CatmullRom, BezierFormMatchesThePyramid) {
  for (bool closed : {false, true}) {
    for (Parameterization p : kAll) {
      const std::vector<double> xy = closed ? edit_test::loop(11) : edit_test::wave(23);
      const CatmullRom c = make(xy, closed, p);
      double seg[8], worst = 0;
      for (int s = 0; s < c.segment_count(); ++s) {
        c.segment_bezier(s, seg);
        for (int k = 0; k <= 20; ++k) {
          const double u = k / 20.0;
          worst = std::max(worst, (bezier_point(seg, u) - c.point(s, u)).norm());
        }
      }
      EXPECT_LE(worst, 1e-12 * c.size()) << "closed " << closed << " param " << int(p);
      // The shared model's layout: 3n+1 points open, 3n closed, anchors at the control points.
      std::vector<double> pts;
      std::vector<JunctionInfo> tags;
      c.bezier(pts, tags);
      EXPECT_EQ(int(pts.size() / 2), closed ? 3 * c.segment_count() : 3 * c.segment_count() + 1);
      for (int i = 0; i < c.count(); ++i) {
        EXPECT_EQ(pts[6 * size_t(i)], xy[2 * size_t(i)]);
        EXPECT_EQ(pts[6 * size_t(i) + 1], xy[2 * size_t(i) + 1]);
      }
      EXPECT_EQ(int(tags.size()), closed ? c.count() : c.count() - 2);
    }
  }
}

TEST(CatmullRom, UniformTangentsAreHalfTheNeighbourChord) {
  const std::vector<double> xy = edit_test::wave(9);
  const CatmullRom c = make(xy, false, Parameterization::kUniform);
  for (int i = 1; i < c.count() - 1; ++i) {
    const Vec2 expected = 0.5 * (c.control_point(i + 1) - c.control_point(i - 1));
    EXPECT_LT((c.tangent(i) - expected).norm(), 1e-14 * c.size());
    // Bézier handles a third of the tangent away: P_i ± T_i / 3.
    double seg[8];
    c.segment_bezier(i, seg);
    EXPECT_LT((vec2_at(seg, 1) - (c.control_point(i) + expected / 3.0)).norm(), 1e-14 * c.size());
  }
  // A repeated end point: T_0 = (P_1 - P_0) / 2.
  EXPECT_LT((c.tangent(0) - 0.5 * (c.control_point(1) - c.control_point(0))).norm(), 1e-14 * c.size());
}

TEST(CatmullRom, EndTangentIsHalfTheFirstChordInEveryParameterization) {
  const std::vector<double> xy = edit_test::wave(6);
  for (Parameterization p : kAll) {
    const CatmullRom c = make(xy, false, p);
    const double d = c.interval(0);
    // Handle of the first segment = P0 + m0 d / 3 with m0 = (P1 - P0) / (2 d): (P1 - P0) / 6.
    double seg[8];
    c.segment_bezier(0, seg);
    EXPECT_LT((vec2_at(seg, 1) - (c.control_point(0) + (c.control_point(1) - c.control_point(0)) / 6.0)).norm(),
              1e-14 * c.size() + 1e-15 * d);
  }
}

TEST(CatmullRom, ContinuityTagsAreAsConstructed) {
  const std::vector<double> xy = edit_test::wave(8);
  std::vector<double> pts;
  std::vector<JunctionInfo> tags;
  make(xy, false, Parameterization::kUniform).bezier(pts, tags);
  for (const JunctionInfo& t : tags) EXPECT_EQ(t.kind, Continuity::kC1);
  const CatmullRom c = make(xy, false, Parameterization::kCentripetal);
  c.bezier(pts, tags);
  // G1 with the ratio of the knot intervals, which the handles' lengths show.
  for (size_t j = 0; j < tags.size(); ++j) {
    EXPECT_EQ(tags[j].kind, Continuity::kG1);
    const int i = int(j) + 1;
    EXPECT_NEAR(tags[j].ratio, c.interval(i) / c.interval(i - 1), 1e-15);
    const Vec2 p = vec2_at(pts.data(), 3 * i), in = vec2_at(pts.data(), 3 * i - 1),
               out = vec2_at(pts.data(), 3 * i + 1);
    EXPECT_NEAR((out - p).norm() / (p - in).norm(), tags[j].ratio, 1e-12);
    EXPECT_NEAR(cross(out - p, p - in), 0.0, 1e-12 * c.size() * c.size());
  }
}

TEST(CatmullRom, CentripetalHasNoCuspWhereUniformDoes) {
  // The classic case: a short middle segment between two long ones.
  const std::vector<double> xy = {0, 0, 1, 1, 1.1, 1, 2.1, 0};
  const CatmullRom uniform = make(xy, false, Parameterization::kUniform);
  const CatmullRom centripetal = make(xy, false, Parameterization::kCentripetal);
  EXPECT_LT(min_forward_speed(uniform, 1), 0.0);      // the middle segment loops back
  EXPECT_GT(min_forward_speed(centripetal, 1), 0.0);  // it runs forward all the way
}

TEST(CatmullRom, NormalsAreUnitAndPerpendicular) {
  const CatmullRom c = make(edit_test::loop(10), true, Parameterization::kCentripetal);
  for (int i = 0; i < c.count(); ++i) {
    const Vec2 n = c.normal_at(i), t = c.tangent(i);
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    EXPECT_NEAR(n.dot(t), 0.0, 1e-12 * t.norm());
    EXPECT_GT(cross(t, n), 0.0);  // left of the tangent
    // Matches the curve's own normal at the control point.
    EXPECT_LT((c.unit_normal(i, 0.0) - n).norm(), 1e-12);
  }
  // Counter-clockwise loop: left normals point inside.
  EXPECT_LT(c.normal_at(0).x(), 0.0);
}

TEST(CatmullRom, TangentOverrideSetsTheHandlesAndKeepsInterpolation) {
  const std::vector<double> xy = edit_test::wave(7);
  CatmullRom c = make(xy, false, Parameterization::kUniform);
  const Vec2 t(0.0, 4.0);
  c.set_tangent(3, t);
  EXPECT_TRUE(c.tangent_overridden(3));
  EXPECT_EQ(c.tangent(3), t);
  double seg[8];
  c.segment_bezier(3, seg);
  EXPECT_LT((vec2_at(seg, 1) - (c.control_point(3) + t / 3.0)).norm(), 1e-14);
  c.segment_bezier(2, seg);
  EXPECT_LT((vec2_at(seg, 2) - (c.control_point(3) - t / 3.0)).norm(), 1e-14);
  EXPECT_LT((c.point(2, 1.0) - c.control_point(3)).norm(), 1e-12);
  // Other segments are untouched (local control).
  const CatmullRom plain = make(xy, false, Parameterization::kUniform);
  double a[8], b[8];
  c.segment_bezier(0, a);
  plain.segment_bezier(0, b);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(a[k], b[k]);
  c.clear_tangent(3);
  c.segment_bezier(3, a);
  plain.segment_bezier(3, b);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(a[k], b[k]);
}

TEST(CatmullRom, CoincidentPointsStayFinite) {
  const std::vector<double> xy = {0, 0, 1, 0, 1, 0, 2, 1};
  for (Parameterization p : kAll) {
    const CatmullRom c = make(xy, false, p);
    for (int s = 0; s < c.segment_count(); ++s)
      for (double u : {0.0, 0.3, 1.0}) EXPECT_TRUE(c.point(s, u).allFinite());
    // With knots from the chords the segment between the twins is a point; uniform knots loop there.
    if (p != Parameterization::kUniform) EXPECT_NEAR(c.segment_length(1), 0.0, 1e-9);
  }
}

TEST(CatmullRom, RejectsBadInputAndKeepsTheCurve) {
  CatmullRom c = make({0, 0, 1, 1, 2, 0}, false, Parameterization::kCentripetal);
  const double one[2] = {0, 0};
  EXPECT_NE(c.set(one, 1, false).find("at least 2"), std::string::npos);
  const double two[4] = {0, 0, 1, 1};
  EXPECT_NE(c.set(two, 2, true).find("at least 3"), std::string::npos);
  const double nan[4] = {0, 0, std::nan(""), 1};
  EXPECT_NE(c.set(nan, 2, false).find("control point 1 has a non-finite x"), std::string::npos);
  const double huge[4] = {0, 0, 1e300, 1};
  EXPECT_NE(c.set(huge, 2, false).find("control point 1 has an x coordinate beyond"), std::string::npos);
  EXPECT_EQ(c.count(), 3);
}
