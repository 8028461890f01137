// Cubic Bézier kernels against closed forms and independent computations.
#include "common/bezier.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <random>

using namespace splinekit;

namespace {

// A quarter of the unit circle by the classic cubic: handles at k = 4/3 (sqrt 2 - 1).
const double kK = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0);
const double kQuarter[8] = {1, 0, 1, kK, kK, 1, 0, 1};

// Straight segment from (0,0) to (3,4) with evenly spaced handles: B(t) = t (3,4).
const double kLine[8] = {0, 0, 1, 4.0 / 3, 2, 8.0 / 3, 3, 4};

double power_eval(const double* c, double t, int axis) {
  // Independent evaluation through the power basis: a + b t + c t^2 + d t^3.
  const double p0 = c[axis], p1 = c[2 + axis], p2 = c[4 + axis], p3 = c[6 + axis];
  const double a = p0, b = 3 * (p1 - p0), cc = 3 * (p0 - 2 * p1 + p2), d = p3 - 3 * p2 + 3 * p1 - p0;
  return a + t * (b + t * (cc + t * d));
}

void random_cubic(std::mt19937& rng, double* c) {
  std::uniform_real_distribution<double> u(-10, 10);
  for (int i = 0; i < 8; ++i) c[i] = u(rng);
}

}  // namespace

TEST(Bernstein, PartitionOfUnityAndEndValues) {
  for (double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) EXPECT_NEAR(bernstein(t).sum(), 1.0, 1e-15);
  EXPECT_EQ(bernstein(0.0), Eigen::Vector4d(1, 0, 0, 0));
  EXPECT_EQ(bernstein(1.0), Eigen::Vector4d(0, 0, 0, 1));
  EXPECT_NEAR(bernstein(0.5)[1], 3.0 / 8.0, 1e-15);
}

TEST(Bernstein, GramMatrixMatchesClosedFormAndQuadrature) {
  const Eigen::Matrix4d g = bernstein_gram();
  // Known entries: ∫(1-t)^6 = 1/7, ∫ 3t(1-t)^5 (1-t) ... = 3/42 = 1/14, ∫ 9 t^2 (1-t)^4 = 9/105.
  EXPECT_NEAR(g(0, 0), 1.0 / 7.0, 1e-16);
  EXPECT_NEAR(g(0, 1), 1.0 / 14.0, 1e-16);
  EXPECT_NEAR(g(1, 1), 9.0 / 105.0, 1e-16);
  EXPECT_NEAR(g(0, 3), 1.0 / 140.0, 1e-16);
  EXPECT_TRUE(g.isApprox(g.transpose(), 0));
  // ∫ b bᵀ summed over all entries = ∫ (Σ b)^2 = 1.
  EXPECT_NEAR(g.sum(), 1.0, 1e-15);
  // Independent: composite Simpson with 2000 panels (exact for degree 6 up to rounding).
  Eigen::Matrix4d q = Eigen::Matrix4d::Zero();
  const int n = 2000;
  for (int k = 0; k <= n; ++k) {
    const double t = double(k) / n, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    const Eigen::Vector4d b = bernstein(t);
    q += w * b * b.transpose();
  }
  q /= 3.0 * n;
  EXPECT_LT((q - g).cwiseAbs().maxCoeff(), 1e-12);
  // Positive definite: the basis is linearly independent.
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(g).eigenvalues().minCoeff(), 0.0);
}

TEST(Bezier, PointMatchesPowerBasisAndEndpoints) {
  std::mt19937 rng(7);
  double c[8];
  for (int trial = 0; trial < 100; ++trial) {
    random_cubic(rng, c);
    for (double t : {0.0, 0.25, 0.5, 0.8, 1.0}) {
      const Vec2 p = bezier_point(c, t);
      EXPECT_NEAR(p.x(), power_eval(c, t, 0), 1e-12);
      EXPECT_NEAR(p.y(), power_eval(c, t, 1), 1e-12);
    }
    EXPECT_EQ(bezier_point(c, 0.0), Vec2(c[0], c[1]));
    EXPECT_EQ(bezier_point(c, 1.0), Vec2(c[6], c[7]));
  }
}

TEST(Bezier, DerivativesMatchFiniteDifferencesAndEndTangents) {
  std::mt19937 rng(11);
  double c[8];
  for (int trial = 0; trial < 50; ++trial) {
    random_cubic(rng, c);
    // End tangents are 3 (P1 - P0) and 3 (P3 - P2).
    EXPECT_TRUE(bezier_derivative(c, 0.0, 1).isApprox(3 * Vec2(c[2] - c[0], c[3] - c[1]), 1e-14));
    EXPECT_TRUE(bezier_derivative(c, 1.0, 1).isApprox(3 * Vec2(c[6] - c[4], c[7] - c[5]), 1e-14));
    const double h = 1e-5;
    for (double t : {0.2, 0.5, 0.7}) {
      for (int order = 1; order <= 3; ++order) {
        const Vec2 fd = (bezier_derivative(c, t + h, order - 1) - bezier_derivative(c, t - h, order - 1)) / (2 * h);
        EXPECT_LT((fd - bezier_derivative(c, t, order)).norm(), 1e-5 * (1 + fd.norm())) << "order " << order;
      }
    }
    EXPECT_EQ(bezier_derivative(c, 0.3, 4), Vec2::Zero());
  }
}

TEST(Bezier, SplitReproducesBothHalves) {
  std::mt19937 rng(3);
  double c[8], l[8], r[8];
  for (int trial = 0; trial < 50; ++trial) {
    random_cubic(rng, c);
    const double t = 0.1 + 0.8 * std::uniform_real_distribution<double>(0, 1)(rng);
    bezier_split(c, t, l, r);
    for (double s : {0.0, 0.3, 0.6, 1.0}) {
      EXPECT_LT((bezier_point(l, s) - bezier_point(c, s * t)).norm(), 1e-12);
      EXPECT_LT((bezier_point(r, s) - bezier_point(c, t + s * (1 - t))).norm(), 1e-12);
    }
    // Tangent scaling: the left half's end tangent is t times the original's.
    EXPECT_LT((bezier_derivative(l, 1, 1) - t * bezier_derivative(c, t, 1)).norm(), 1e-10);
  }
}

TEST(Bezier, ArcLengthOfLineAndQuarterCircle) {
  EXPECT_NEAR(bezier_arc_length(kLine), 5.0, 1e-12);
  EXPECT_NEAR(bezier_arc_length(kLine, 0.25, 0.75), 2.5, 1e-12);
  EXPECT_NEAR(bezier_arc_length(kLine, 0.75, 0.25), -2.5, 1e-12);
  // The classic quarter-circle cubic overshoots the circle by at most 2.7e-4: its length is
  // within a few 1e-4 of pi/2 (and above it, the cubic bulges outward).
  const double q = bezier_arc_length(kQuarter);
  EXPECT_NEAR(q, kPi / 2, 3e-4);
  EXPECT_GT(q, kPi / 2);
  // Independent: a 200k-piece polyline approaches from below to ~1e-10.
  double poly = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k)
    poly += (bezier_point(kQuarter, double(k + 1) / n) - bezier_point(kQuarter, double(k) / n)).norm();
  EXPECT_NEAR(q, poly, 1e-9);
  EXPECT_GE(q, poly);
}

TEST(Bezier, ArcLengthWithCuspStaysAccurate) {
  // A cusp: B'(t) vanishes at t = 1/2. B(t) = (3t(1-t)... ) — control polygon folded back.
  const double c[8] = {0, 0, 1, 1, 0, 1, 1, 0};
  double poly = 0;
  const int n = 400000;
  for (int k = 0; k < n; ++k) poly += (bezier_point(c, double(k + 1) / n) - bezier_point(c, double(k) / n)).norm();
  EXPECT_NEAR(bezier_arc_length(c, 0, 1, 1e-10), poly, 1e-8);
}

TEST(Bezier, BoundsAreTightOnTheCurve) {
  double b[4];
  bezier_bounds(kQuarter, b);
  EXPECT_NEAR(b[0], 0, 1e-15);
  EXPECT_NEAR(b[1], 0, 1e-15);
  EXPECT_NEAR(b[2], 1, 1e-15);
  EXPECT_NEAR(b[3], 1, 1e-15);
  // Extremum inside: P = (0,0),(0,3),(3,3),(3,0) peaks at y = 9/4 at t = 1/2 (hull says 3).
  const double arch[8] = {0, 0, 0, 3, 3, 3, 3, 0};
  bezier_bounds(arch, b);
  EXPECT_NEAR(b[3], 2.25, 1e-14);
  // Random curves: bounds contain dense samples and are touched by them.
  std::mt19937 rng(5);
  double c[8];
  for (int trial = 0; trial < 100; ++trial) {
    random_cubic(rng, c);
    bezier_bounds(c, b);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k <= 20000; ++k) {
      const Vec2 p = bezier_point(c, k / 20000.0);
      for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    }
    for (int a = 0; a < 2; ++a) {
      EXPECT_LE(b[a], lo[a] + 1e-12);
      EXPECT_GE(b[2 + a], hi[a] - 1e-12);
      EXPECT_NEAR(b[a], lo[a], 1e-6);
      EXPECT_NEAR(b[2 + a], hi[a], 1e-6);
    }
  }
}

TEST(Bezier, SampleHitsEndpointsAndEvenParameters) {
  double out[10];
  bezier_sample(kLine, 5, out);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(out[2 * k], 3.0 * k / 4, 1e-14);
    EXPECT_NEAR(out[2 * k + 1], 4.0 * k / 4, 1e-14);
  }
}

TEST(Spline, SegmentsAndBoundsOfOpenAndClosed) {
  EXPECT_EQ(spline_segment_count(1, false), 0);
  EXPECT_EQ(spline_segment_count(4, false), 1);
  EXPECT_EQ(spline_segment_count(7, false), 2);
  EXPECT_EQ(spline_segment_count(12, true), 4);
  // Full circle from four quarter cubics (closed, 12 points).
  double pts[24];
  for (int q = 0; q < 4; ++q) {
    const double ang = q * kPi / 2;
    const Vec2 a(std::cos(ang), std::sin(ang)), t(-std::sin(ang), std::cos(ang));
    const Vec2 h0 = a + kK * t;
    const Vec2 nxt(std::cos(ang + kPi / 2), std::sin(ang + kPi / 2));
    const Vec2 h1 = nxt + kK * a;  // incoming handle of the next anchor
    pts[6 * q] = a.x(), pts[6 * q + 1] = a.y();
    pts[6 * q + 2] = h0.x(), pts[6 * q + 3] = h0.y();
    pts[6 * q + 4] = h1.x(), pts[6 * q + 5] = h1.y();
  }
  double seg[8];
  spline_segment(pts, 12, true, 3, seg);
  EXPECT_EQ(seg[6], pts[0]);
  EXPECT_EQ(seg[7], pts[1]);
  double b[4];
  spline_bounds(pts, 12, true, b);
  EXPECT_NEAR(b[0], -1, 1e-12);
  EXPECT_NEAR(b[1], -1, 1e-12);
  EXPECT_NEAR(b[2], 1, 1e-12);
  EXPECT_NEAR(b[3], 1, 1e-12);
  const double lone[2] = {2, 5};
  spline_bounds(lone, 1, false, b);
  EXPECT_EQ(b[0], 2);
  EXPECT_EQ(b[3], 5);
}
