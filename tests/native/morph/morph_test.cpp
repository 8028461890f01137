#include "morph/morph.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/bezier.h"
#include "test_shapes.h"

using namespace splinekit;
using namespace splinekit::morph;

namespace {

std::vector<double> frame(Morph& m, double t, Interpolation mode = Interpolation::kLinear) {
  std::vector<double> out(2 * size_t(m.point_count()));
  m.evaluate(t, mode, out.data());
  return out;
}

// Largest distance from points sampled on the frame's contours to the curves of `set` (dense
// sampling refined by ternary search on the nearest segment).
double distance_to(const std::vector<double>& pts, const Morph& m, const SplineSet& set) {
  double worst = 0;
  double seg[8], s2[8];
  for (int c = 0; c < m.contour_count(); ++c) {
    const int count = m.counts()[size_t(c)];
    const bool closed = m.closed()[size_t(c)] != 0;
    for (int k = 0; k < spline_segment_count(count, closed); ++k) {
      spline_segment(pts.data() + 2 * size_t(m.starts()[size_t(c)]), count, closed, k, seg);
      for (int i = 0; i <= 8; ++i) {
        const Vec2 q = bezier_point(seg, i / 8.0);
        double best = 1e300;
        for (int s = 0; s < set.spline_count(); ++s) {
          for (int kk = 0; kk < spline_segment_count(set.count[s], set.closed[s] != 0); ++kk) {
            spline_segment(set.spline_points(s), set.count[s], set.closed[s] != 0, kk, s2);
            double lo = 0, hi = 1, bu = 0, bd = 1e300;
            for (int u = 0; u <= 200; ++u) {
              const double d = (bezier_point(s2, u / 200.0) - q).norm();
              if (d < bd) bd = d, bu = u / 200.0;
            }
            lo = std::max(0.0, bu - 0.005);
            hi = std::min(1.0, bu + 0.005);
            for (int it = 0; it < 100; ++it) {
              const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
              if ((bezier_point(s2, m1) - q).norm() < (bezier_point(s2, m2) - q).norm())
                hi = m2;
              else
                lo = m1;
            }
            best = std::min({best, bd, (bezier_point(s2, (lo + hi) / 2) - q).norm()});
          }
        }
        worst = std::max(worst, best);
      }
    }
  }
  return worst;
}

SplineSet one(const std::vector<double>& p, bool closed = true) { return test::set_of({p}, {closed}); }

}  // namespace

TEST(Morph, IdenticalKeysGiveZeroWorkAndIdentityFrames) {
  const SplineSet a = test::set_of({test::d_shape(5), test::circle(20, 0, 3, 4)}, {true, true});
  Morph m;
  ASSERT_EQ(m.setup(a, a, {}, {}), "");
  EXPECT_EQ(m.work(), 0.0);
  ASSERT_EQ(m.contour_count(), 2);
  const auto f0 = frame(m, 0.0), f5 = frame(m, 0.5), f1 = frame(m, 1.0);
  for (size_t i = 0; i < f0.size(); ++i) {
    EXPECT_NEAR(f5[i], f0[i], 1e-12);
    EXPECT_NEAR(f1[i], f0[i], 1e-12);
  }
  const auto in = frame(m, 0.5, Interpolation::kIntrinsic);
  for (size_t i = 0; i < f0.size(); ++i) EXPECT_NEAR(in[i], f0[i], 1e-9);
  EXPECT_LT(distance_to(f5, m, a), 1e-9 * 30);
}

TEST(Morph, ScaledCopyCostsStretchingOnly) {
  const auto d = test::d_shape(2);
  const SplineSet a = one(d), b = one(test::transformed(d, 2.5, 0, 0, 2.5, 1, 1));
  MorphOptions o;
  Morph m;
  ASSERT_EQ(m.setup(a, b, o, {}), "");
  EXPECT_GT(m.work(), 0.0);
  o.work.stretching = 0;  // without stretching nothing is left: no bending, no kinking
  ASSERT_EQ(m.setup(a, b, o, {}), "");
  EXPECT_NEAR(m.work(), 0.0, 1e-12);
}

TEST(Morph, FramesAtZeroAndOneTraceTheKeys) {
  const SplineSet a = test::set_of({test::d_shape(10), test::circle(3, 0, 2, 4)}, {true, true});
  const SplineSet b =
      test::set_of({test::polygon({{0, 0}, {12, -1}, {14, 9}, {1, 11}}), test::circle(6, 5, 1.5, 3)}, {true, true});
  Morph m;
  ASSERT_EQ(m.setup(a, b, {}, {}), "");
  const double size = 20;
  EXPECT_LT(distance_to(frame(m, 0), m, a), 1e-9 * size);
  EXPECT_LT(distance_to(frame(m, 1), m, b), 1e-9 * size);
  EXPECT_LT(distance_to(frame(m, 0, Interpolation::kIntrinsic), m, a), 1e-9 * size);
  EXPECT_LT(distance_to(frame(m, 1, Interpolation::kIntrinsic), m, b), 1e-9 * size);
}

TEST(Morph, C1KeysBlendWithoutTheBezierKink) {
  // Fig. 3: both keys are C1 at every join but with different handle ratios. Interpolating the
  // Bézier points directly kinks the joins; interpolating B-spline control points and knots does not.
  const auto a = test::circle(0, 0, 10, 4);
  const double c = std::cos(0.3), s = std::sin(0.3);
  auto b = test::transformed(test::transformed(test::circle(0, 0, 10, 4), c, s, -s, c, 0, 0), 1.8, 0, 0, 0.6, 0, 0);
  const double factor[4] = {2.0, 0.5, 1.5, 1 / 1.5};  // their product is 1: the ratios close up
  // Make B's joins C1 with unequal handle lengths: stretch the outgoing handle at each anchor.
  for (int k = 0; k < 4; ++k) {
    const int p = 3 * k, h = 3 * k + 1, hin = (3 * k + 11) % 12;
    const double f = factor[k];
    b[2 * h] = b[2 * p] + f * (b[2 * p] - b[2 * hin]);
    b[2 * h + 1] = b[2 * p + 1] + f * (b[2 * p + 1] - b[2 * hin + 1]);
  }
  Morph m;
  MorphOptions o;
  o.segment_limit = 0;
  ASSERT_EQ(m.setup(one(a), one(b), o, {}), "");
  const auto& coupled = m.coupled();
  int smooth = 0;
  for (uint8_t c : coupled) smooth += c;
  EXPECT_EQ(smooth, int(coupled.size()));  // every join is C1 in both keys and stays coupled
  for (double t : {0.25, 0.5, 0.75}) {
    for (auto mode : {Interpolation::kLinear, Interpolation::kIntrinsic}) {
      const auto f = frame(m, t, mode);
      const int count = m.point_count();
      for (int k = 0; k < count / 3; ++k) {
        const Vec2 hin = vec2_at(f.data(), (3 * k + count - 1) % count), p = vec2_at(f.data(), 3 * k),
                   hout = vec2_at(f.data(), 3 * k + 1);
        // G1 at least (within the keys' own tolerance), and C1 for the knot intervals' ratio.
        EXPECT_LT(std::abs(cross(p - hin, hout - p)) / ((p - hin).norm() * (hout - p).norm()), 1e-9) << t;
      }
    }
  }
  // The naive Bézier blend of the same layout does kink.
  const auto& ka = m.blend(0).key(0);
  const auto& kb = m.blend(0).key(1);
  double worst = 0;
  const int count = m.point_count();
  for (int k = 0; k < count / 3; ++k) {
    auto lerp = [&](int i) { return Vec2(0.5 * (ka[2 * i] + kb[2 * i]), 0.5 * (ka[2 * i + 1] + kb[2 * i + 1])); };
    const Vec2 hin = lerp((3 * k + count - 1) % count), p = lerp(3 * k), hout = lerp(3 * k + 1);
    worst = std::max(worst, std::abs(cross(p - hin, hout - p)) / ((p - hin).norm() * (hout - p).norm()));
  }
  EXPECT_GT(worst, 1e-3);
}

TEST(Morph, BothDirectionsOfAClosedContourGiveTheSameWork) {
  const auto a = test::d_shape(4);
  const auto b = test::polygon({{0, 0}, {5, 1}, {4, 6}, {-1, 4}, {-2, 2}});
  Morph f, r;
  ASSERT_EQ(f.setup(one(a), one(b), {}, {}), "");
  ASSERT_EQ(r.setup(one(a), one(test::reversed_points(b, true)), {}, {}), "");
  EXPECT_NEAR(f.work(), r.work(), 1e-9 * f.work());
  EXPECT_NE(f.contours()[0].reversed, r.contours()[0].reversed);
}

TEST(Morph, TranslatedCopyBlendsThroughTranslatedCopies) {
  const auto d = test::d_shape(3);
  Morph m;
  ASSERT_EQ(m.setup(one(d), one(test::transformed(d, 1, 0, 0, 1, 7, -2)), {}, {}), "");
  EXPECT_NEAR(m.work(), 0.0, 1e-12);
  const auto f0 = frame(m, 0), f = frame(m, 0.3);
  for (size_t i = 0; i < f.size(); i += 2) {
    EXPECT_NEAR(f[i] - f0[i], 0.3 * 7, 1e-9);
    EXPECT_NEAR(f[i + 1] - f0[i + 1], 0.3 * -2, 1e-9);
  }
}

TEST(Morph, RotatedCopyBlendsThroughRigidCopiesWhenIntrinsic) {
  const auto d = test::d_shape(3);
  const double c = std::cos(2.0), s = std::sin(2.0);
  Morph m;
  MorphOptions paper;  // the paper's work: lengths and angles only, blind to a rotation of one key
  paper.work.travel = 0;
  ASSERT_EQ(m.setup(one(d), one(test::transformed(d, c, s, -s, c, 4, 1)), paper, {}), "");
  EXPECT_NEAR(m.work(), 0.0, 1e-9);
  const auto f0 = frame(m, 0), f = frame(m, 0.5, Interpolation::kIntrinsic), lin = frame(m, 0.5);
  double worst = 0, shrink = 0;
  for (size_t i = 0; i < f.size(); i += 2)
    for (size_t j = 0; j < f.size(); j += 2) {
      const double d0 = std::hypot(f0[i] - f0[j], f0[i + 1] - f0[j + 1]);
      worst = std::max(worst, std::abs(std::hypot(f[i] - f[j], f[i + 1] - f[j + 1]) - d0));
      shrink = std::max(shrink, d0 - std::hypot(lin[i] - lin[j], lin[i + 1] - lin[j + 1]));
    }
  EXPECT_LT(worst, 1e-9);  // intrinsic: a rigid copy
  EXPECT_GT(shrink, 0.5);  // linear: the blend shrinks (cos 1 of the way round)
}

TEST(Morph, MovingRotatingOrScalingBothKeysMovesTheBlend) {
  const auto a = test::d_shape(4);
  const auto b = test::polygon({{0, 0}, {5, 1}, {4, 6}, {-1, 4}});
  const double c = 1.7 * std::cos(0.4), s = 1.7 * std::sin(0.4);
  Morph m, mt;
  ASSERT_EQ(m.setup(one(a), one(b), {}, {}), "");
  ASSERT_EQ(
      mt.setup(one(test::transformed(a, c, s, -s, c, 3, 9)), one(test::transformed(b, c, s, -s, c, 3, 9)), {}, {}), "");
  EXPECT_NEAR(m.work(), mt.work(), 1e-9 * m.work());
  for (auto mode : {Interpolation::kLinear, Interpolation::kIntrinsic}) {
    const auto f = test::transformed(frame(m, 0.4, mode), c, s, -s, c, 3, 9), g = frame(mt, 0.4, mode);
    ASSERT_EQ(f.size(), g.size());
    for (size_t i = 0; i < f.size(); ++i) ASSERT_NEAR(f[i], g[i], 1e-9) << "mode " << int(mode) << " at " << i;
  }
}

TEST(Morph, ABEqualsBAReversed) {
  const auto a = test::d_shape(4);
  const auto b = test::polygon({{0, 0}, {5, 1}, {4, 6}, {-1, 4}});
  Morph ab, ba;
  ASSERT_EQ(ab.setup(one(a), one(b), {}, {}), "");
  ASSERT_EQ(ba.setup(one(b), one(a), {}, {}), "");
  EXPECT_NEAR(ab.work(), ba.work(), 1e-9 * ab.work());
  // Same curves (up to start and direction): compare sampled frames both ways by distance.
  const auto f = frame(ab, 0.3), g = frame(ba, 0.7);
  SplineSet sg = test::set_of({g}, {true});
  EXPECT_LT(distance_to(f, ab, sg), 1e-6);
}

TEST(Morph, UnpairedContourGrowsFromAPointInsideItsPartnersRegion) {
  // A: a disc with a hole; B: a disc without. The hole shrinks to a point inside B's disc.
  const SplineSet a =
      test::set_of({test::circle(0, 0, 10, 4), test::reversed_points(test::circle(0, 0, 4, 4), true)}, {true, true});
  const SplineSet b = test::set_of({test::circle(30, 0, 10, 4)}, {true});
  Morph m;
  ASSERT_EQ(m.setup(a, b, {}, {}), "");
  ASSERT_EQ(m.contour_count(), 2);
  EXPECT_EQ(m.contours()[1].contour_b, -1);
  const auto f1 = frame(m, 1);
  const int s = m.starts()[1];
  for (int i = 0; i < m.counts()[1]; ++i) {
    EXPECT_NEAR(f1[2 * (s + i)], 30, 1e-9);  // the hole's inside point (its centre) carried into B's box
    EXPECT_NEAR(f1[2 * (s + i) + 1], 0, 1e-9);
  }
}

TEST(Morph, PinsHoldTheirPoints) {
  const auto a = test::circle(0, 0, 10, 8);
  const auto b = test::circle(0, 0, 10, 8);
  // Pin A's (10, 0) to B's (0, 10): the identity is no longer allowed; the blend turns by 90°.
  Morph m;
  ASSERT_EQ(m.setup(one(a), one(b), {}, {{10, 0, 0, 10}}), "");
  EXPECT_EQ(m.contours()[0].pins, 1);
  const auto f0 = frame(m, 0), f1 = frame(m, 1);
  bool held = false;
  for (int k = 0; k < m.point_count(); k += 3)
    if (std::hypot(f0[2 * k] - 10, f0[2 * k + 1]) < 1e-9 && std::hypot(f1[2 * k], f1[2 * k + 1] - 10) < 1e-9)
      held = true;
  EXPECT_TRUE(held);
}

TEST(Morph, ContoursOfZeroLengthAreLeftOutAndIndicesStayTheGivenOnes) {
  // A lone point ("M x y Z") between two real contours: it draws nothing and is not blended.
  const SplineSet a = test::set_of({{5, 5, 5, 5, 5, 5}, test::d_shape(4)}, {true, true});
  const SplineSet b = test::set_of({test::circle(0, 0, 3, 4)}, {true});
  Morph m;
  ASSERT_EQ(m.setup(a, b, {}, {}), "");
  ASSERT_EQ(m.contour_count(), 1);
  EXPECT_EQ(m.contours()[0].contour_a, 1);
  EXPECT_EQ(m.contours()[0].contour_b, 0);
  const SplineSet dots = test::set_of({{5, 5, 5, 5, 5, 5}}, {true});
  EXPECT_NE(m.setup(dots, b, {}, {}).find("no contour of nonzero length"), std::string::npos);
  EXPECT_EQ(m.contour_count(), 1);  // the previous morph is kept
}

TEST(Morph, BadInputIsRefusedWithAMessage) {
  Morph m;
  SplineSet empty;
  EXPECT_NE(m.setup(empty, one(test::d_shape()), {}, {}).find("no contour"), std::string::npos);
  SplineSet nan = one(test::d_shape());
  nan.points[3] = NAN;
  EXPECT_NE(m.setup(nan, one(test::d_shape()), {}, {}), "");
  MorphOptions o;
  o.work.kink_exponent = -1;
  EXPECT_NE(m.setup(one(test::d_shape()), one(test::d_shape()), o, {}).find("e_k"), std::string::npos);
  EXPECT_NE(m.setup(one(test::d_shape()), one(test::d_shape()), {}, {{NAN, 0, 0, 0}}).find("pin 0"), std::string::npos);
}
