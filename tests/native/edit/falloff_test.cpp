// The drop-off functions (equations 1–3, re-derived) and the 2D slerp of §3.4.
#include "edit/falloff.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace splinekit;
using namespace splinekit::edit;

namespace {

FalloffOptions options(Falloff kind, double alpha = 1.0, double sigma = 1.0 / 3.0) {
  FalloffOptions o;
  o.kind = kind;
  o.alpha = alpha;
  o.sigma = sigma;
  return o;
}

// The textbook slerp between unit vectors (valid away from the 180° case).
Vec2 textbook_slerp(const Vec2& a, const Vec2& b, double t) {
  const double theta = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  if (theta < 1e-12) return a;
  return (std::sin((1 - t) * theta) * a + std::sin(t * theta) * b) / std::sin(theta);
}

}  // namespace

TEST(Falloff, EachIsOneAtTheDraggedPointZeroAtTheEndsAndMonotone) {
  for (FalloffOptions o : {options(Falloff::kLinear), options(Falloff::kGaussian), options(Falloff::kGaussian, 1, 0.15),
                           options(Falloff::kCosine), options(Falloff::kCosine, 0.1), options(Falloff::kCosine, 4.0)}) {
    EXPECT_EQ(falloff(0.0, o), 1.0);
    EXPECT_EQ(falloff(1.0, o), 0.0);
    double previous = 1.0;
    for (int k = 1; k <= 10000; ++k) {
      const double s = falloff(k / 10000.0, o);
      EXPECT_LE(s, previous) << "kind " << int(o.kind) << " at " << k;
      EXPECT_GE(s, 0.0);
      previous = s;
    }
    // Strictly inside the window every point moves.
    EXPECT_GT(falloff(0.99, o), 0.0);
    // Outside [0, 1] it is clamped: nothing beyond the window's end moves.
    EXPECT_EQ(falloff(1.5, o), 0.0);
  }
}

TEST(Falloff, ClosedForms) {
  EXPECT_DOUBLE_EQ(falloff(0.25, options(Falloff::kLinear)), 0.75);
  // cos(π u / 2)^α: at u = 1/2, (√2/2)^α.
  EXPECT_NEAR(falloff(0.5, options(Falloff::kCosine)), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(falloff(0.5, options(Falloff::kCosine, 2.0)), 0.5, 1e-15);
  EXPECT_NEAR(falloff(0.5, options(Falloff::kCosine, 0.25)), std::pow(0.5, 0.125), 1e-15);
  // Gaussian, σ = 1/3: inside 1 - σ the boundary function is 1, so S = exp(-u² / (2σ²)).
  EXPECT_NEAR(falloff(0.5, options(Falloff::kGaussian)), std::exp(-0.25 / (2.0 / 9.0)), 1e-15);
  // In the last σ: f = ½(1 + cos(π (u - (1 - σ)) / σ)); at the middle of that stretch f = ½.
  const double u = 1.0 - 1.0 / 6.0;
  EXPECT_NEAR(gaussian_boundary(u, 1.0 / 3.0), 0.5, 1e-15);
  EXPECT_NEAR(falloff(u, options(Falloff::kGaussian)), 0.5 * std::exp(-u * u * 4.5), 1e-15);
  EXPECT_EQ(gaussian_boundary(0.5, 1.0 / 3.0), 1.0);
}

TEST(Falloff, AlphaBelowOneSquaresOffAndAboveOneSharpens) {
  for (double u : {0.2, 0.5, 0.8}) {
    EXPECT_GT(falloff(u, options(Falloff::kCosine, 0.25)), falloff(u, options(Falloff::kCosine, 1.0)));
    EXPECT_LT(falloff(u, options(Falloff::kCosine, 3.0)), falloff(u, options(Falloff::kCosine, 1.0)));
  }
}

TEST(Falloff, GaussianBoundaryIsSmooth) {
  // C1 at both ends of the ramp: the one-sided difference quotients vanish.
  const double s = 0.3, h = 1e-6;
  EXPECT_NEAR((gaussian_boundary(1.0 - s + h, s) - 1.0) / h, 0.0, 1e-4);
  EXPECT_NEAR(gaussian_boundary(1.0 - h, s) / h, 0.0, 1e-4);
}

TEST(Slerp, MatchesTheTextbookFormula) {
  for (double a0 : {0.0, 0.7, 2.5, -1.2}) {
    for (double delta : {0.3, -1.1, 2.9, -3.0}) {
      const Vec2 a(std::cos(a0), std::sin(a0)), b(std::cos(a0 + delta), std::sin(a0 + delta));
      for (double t : {0.0, 0.25, 0.5, 0.9, 1.0}) {
        const Vec2 r = slerp(a, b, t);
        EXPECT_LT((r - textbook_slerp(a, b, t)).norm(), 1e-12);
        EXPECT_NEAR(r.norm(), 1.0, 1e-15);
      }
    }
  }
}

TEST(Slerp, HandlesTheHalfTurn) {
  const Vec2 a(0.6, 0.8), b = -a;
  EXPECT_NEAR(signed_angle(a, b), kPi, 1e-15);
  EXPECT_LT((slerp(a, b, 0.0) - a).norm(), 1e-15);
  EXPECT_LT((slerp(a, b, 1.0) - b).norm(), 1e-15);
  // Half way: a turned a quarter counter-clockwise, unit length, no NaN.
  const Vec2 mid = slerp(a, b, 0.5);
  EXPECT_LT((mid - Vec2(-0.8, 0.6)).norm(), 1e-15);
  // Also with -0 in the cross product (b = -a exactly for axis vectors).
  EXPECT_LT((slerp(Vec2(1, 0), Vec2(-1, -0.0), 0.5) - Vec2(0, 1)).norm(), 1e-15);
}
