// The skinning fit (Liu, Jacobson & Gingold 2014 §3–§4) against exact cases and invariants.
#include "skin/rig.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/bezier.h"
#include "skin/shepard.h"

using namespace splinekit;
using namespace splinekit::skin;

namespace {

// Two splines: a closed blob of 6 segments (smooth, G1 and corner junctions) and an open wave.
SplineSet artwork() {
  SplineSet s;
  const int n = 6;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n, r = 10 + 2 * std::cos(3 * a);
    const Vec2 p(20 + r * std::cos(a), 15 + r * std::sin(a)), t(-std::sin(a), std::cos(a));
    const double in = 2.0, out = k % 3 == 0 ? 2.0 : 3.5;  // C1, then G1 with ratio 1.75
    Vec2 hin = p - in * t, hout = p + out * t;
    if (k == 4) hout = p + 3.0 * Vec2(std::cos(a + 0.9), std::sin(a + 0.9));  // a corner
    // Points of segment k-1 end with hin, then anchor p, then hout: store as anchor, hout, (next hin).
    s.points.insert(s.points.end(), {p.x(), p.y(), hout.x(), hout.y()});
    const double a2 = 2 * kPi * (k + 1) / n, r2 = 10 + 2 * std::cos(3 * a2);
    const Vec2 p2(20 + r2 * std::cos(a2), 15 + r2 * std::sin(a2)), t2(-std::sin(a2), std::cos(a2));
    const Vec2 hin2 = p2 - 2.0 * t2;
    s.points.insert(s.points.end(), {hin2.x(), hin2.y()});
    (void)hin;
  }
  s.start.push_back(0);
  s.count.push_back(3 * n);
  s.closed.push_back(1);
  // Open wave of 3 segments with C1 junctions.
  const int base = int(s.points.size() / 2);
  for (int k = 0; k <= 9; ++k) {
    const double x = 40 + 3 * k, y = 10 + ((k % 3) == 0 ? 0 : (k % 3 == 1 ? 4 : -4)) * ((k / 3) % 2 ? -1 : 1);
    s.points.insert(s.points.end(), {x, y});
  }
  // Make the anchors C1: reflect the handle before each interior anchor.
  for (int j = 1; j <= 2; ++j) {
    const int anchor = base + 3 * j;
    s.points[2 * (anchor + 1)] = 2 * s.points[2 * anchor] - s.points[2 * (anchor - 1)];
    s.points[2 * (anchor + 1) + 1] = 2 * s.points[2 * anchor + 1] - s.points[2 * (anchor - 1) + 1];
  }
  s.start.push_back(base);
  s.count.push_back(10);
  s.closed.push_back(0);
  return s;
}

std::vector<Continuity> detected(const SplineSet& s) {
  std::vector<JunctionInfo> info(total_junctions(s));
  spline_set_classify(s, continuity_options_for_size(60.0), info.data());
  std::vector<Continuity> kinds;
  for (const JunctionInfo& j : info) kinds.push_back(j.kind);
  return kinds;
}

const double kHandles[8] = {12, 10, 28, 20, 45, 10, 65, 12};

SkinRig make_rig(const SplineSet& s, const std::vector<Continuity>& kinds, int samples = 100) {
  SkinRig rig;
  SkinOptions o;
  o.samples = samples;
  EXPECT_EQ(rig.setup(s, kinds, 4, o), "");
  rig.use_shepard(kHandles, 2.0);
  EXPECT_EQ(rig.precompute(), "");
  return rig;
}

void identity(double* T, int h) {
  for (int i = 0; i < h; ++i) {
    const double id[6] = {1, 0, 0, 1, 0, 0};
    std::copy(id, id + 6, T + 6 * i);
  }
}

// Random pose: each handle rotates by up to ±60° about itself and moves a little.
std::vector<double> random_pose(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-kPi / 3, kPi / 3), shift(-3, 3), scale(0.8, 1.25);
  std::vector<double> T(24);
  for (int i = 0; i < 4; ++i) {
    const double a = angle(rng), s = scale(rng), hx = kHandles[2 * i], hy = kHandles[2 * i + 1];
    const double c = s * std::cos(a), d = s * std::sin(a);
    // x' = R (x - h) + h + shift
    T[6 * i + 0] = c, T[6 * i + 1] = d, T[6 * i + 2] = -d, T[6 * i + 3] = c;
    T[6 * i + 4] = hx - (c * hx - d * hy) + shift(rng);
    T[6 * i + 5] = hy - (d * hx + c * hy) + shift(rng);
  }
  return T;
}

double max_diff(const double* a, const double* b, size_t n) {
  double m = 0;
  for (size_t i = 0; i < n; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace

TEST(Shepard, PartitionOfUnityInterpolationAndGradient) {
  const double pts[6] = {12, 10, 30, 14, -5, 40};
  double w[12], g[24];
  shepard_weights(kHandles, 4, pts, 3, 2.0, w);
  shepard_gradients(kHandles, 4, pts, 3, 2.0, g);
  EXPECT_EQ(w[0], 1.0);  // at handle 0
  for (int p = 0; p < 3; ++p) {
    double sum = 0;
    for (int i = 0; i < 4; ++i) {
      sum += w[4 * p + i];
      EXPECT_GE(w[4 * p + i], 0.0);
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
  }
  // Closed form for point (30,14): w_i ∝ 1/d_i².
  double inv[4], s = 0;
  for (int i = 0; i < 4; ++i)
    s += inv[i] = 1 / (std::pow(30 - kHandles[2 * i], 2) + std::pow(14 - kHandles[2 * i + 1], 2));
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(w[4 + i], inv[i] / s, 1e-15);
  // Gradient by central differences.
  const double h = 1e-6;
  for (int axis = 0; axis < 2; ++axis) {
    double q[4] = {30, 14, 30, 14}, wq[8];
    q[axis] += h, q[2 + axis] -= h;
    shepard_weights(kHandles, 4, q, 2, 2.0, wq);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(g[(4 + i) * 2 + axis], (wq[i] - wq[4 + i]) / (2 * h), 1e-7);
  }
  for (int i = 0; i < 8; ++i) EXPECT_EQ(g[i], 0.0);  // zero at a handle
}

TEST(SkinRig, DetectsTheArtworkJunctions) {
  const SplineSet s = artwork();
  const std::vector<Continuity> k = detected(s);
  ASSERT_EQ(k.size(), 8u);
  EXPECT_EQ(k[0], Continuity::kC1);  // closed blob: anchors 0 and 3 keep equal handles
  EXPECT_EQ(k[1], Continuity::kG1);
  EXPECT_EQ(k[4], Continuity::kC0);  // the corner
  EXPECT_EQ(k[6], Continuity::kC1);  // wave
}

TEST(SkinRig, IdentityPoseReproducesTheInput) {
  const SplineSet s = artwork();
  SkinRig rig = make_rig(s, detected(s));
  double T[24];
  identity(T, 4);
  const double* X = rig.update(T);
  EXPECT_LT(max_diff(X, s.points.data(), s.points.size()), 1e-9);
  EXPECT_LT(rig.energy(X, T), 1e-18);
}

TEST(SkinRig, ASharedSimilarityGivesItsExactImage) {
  const SplineSet s = artwork();
  SkinRig rig = make_rig(s, detected(s));
  const double a = 0.7, sc = 1.3, c = sc * std::cos(a), d = sc * std::sin(a);
  double T[24];
  for (int i = 0; i < 4; ++i) {
    const double t[6] = {c, d, -d, c, 5, -7};
    std::copy(t, t + 6, T + 6 * i);
  }
  const double* X = rig.update(T);
  for (int k = 0; k < s.point_count(); ++k) {
    const double x = s.points[2 * k], y = s.points[2 * k + 1];
    EXPECT_NEAR(X[2 * k], c * x - d * y + 5, 1e-9);
    EXPECT_NEAR(X[2 * k + 1], d * x + c * y - 7, 1e-9);
  }
  // Any shared affine map too (skew, non-uniform scale): curves map exactly to curves.
  for (int i = 0; i < 4; ++i) {
    const double t[6] = {1.2, 0.3, -0.4, 0.8, 2, 3};
    std::copy(t, t + 6, T + 6 * i);
  }
  // (only when no angle constraint is present: an affine map does not keep angles) — unconstrained:
  SkinRig free = make_rig(s, std::vector<Continuity>(8, Continuity::kC0));
  const double* Y = free.update(T);
  for (int k = 0; k < s.point_count(); ++k) {
    EXPECT_NEAR(Y[2 * k], 1.2 * s.points[2 * k] - 0.4 * s.points[2 * k + 1] + 2, 1e-9);
    EXPECT_NEAR(Y[2 * k + 1], 0.3 * s.points[2 * k] + 0.8 * s.points[2 * k + 1] + 3, 1e-9);
  }
}

TEST(SkinRig, ConstraintsHoldOnRandomPoses) {
  const SplineSet s = artwork();
  std::vector<Continuity> kinds = detected(s);
  kinds[4] = Continuity::kAngle;  // keep the corner's angle
  SkinRig rig = make_rig(s, kinds);
  EXPECT_EQ(rig.constrained_count(), 8);
  std::mt19937 rng(42);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> T = random_pose(rng);
    const double* X = rig.update(T.data());
    EXPECT_LE(rig.constraint_residual(X), 1e-9);
    // Anchors are shared, so C0 holds by construction; and the result is finite.
    for (size_t i = 0; i < s.points.size(); ++i) ASSERT_TRUE(std::isfinite(X[i]));
  }
  // The naive baseline does not keep them (the test can fail).
  const std::vector<double> T = random_pose(rng);
  EXPECT_GT(rig.constraint_residual(rig.baseline(SkinMethod::kNaiveAll, T.data())), 1e-3);
}

TEST(SkinRig, UnconstrainedFitBeatsEveryBaselineOnRandomPoses) {
  const SplineSet s = artwork();
  SkinRig rig = make_rig(s, std::vector<Continuity>(8, Continuity::kC0));
  std::mt19937 rng(7);
  std::vector<double> X;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> T = random_pose(rng);
    X.assign(rig.update(T.data()), rig.update(T.data()) + s.points.size());
    const double fit = rig.energy(X.data(), T.data());
    for (SkinMethod m : {SkinMethod::kNaiveAll, SkinMethod::kNaiveInterpolated, SkinMethod::kNaiveJacobian}) {
      EXPECT_LE(fit, rig.energy(rig.baseline(m, T.data()), T.data()) * (1 + 1e-12)) << int(m);
    }
    // The fit is the minimizer: any perturbation raises the energy.
    std::vector<double> Y = X;
    Y[5] += 1e-3;
    EXPECT_GT(rig.energy(Y.data(), T.data()), fit);
  }
}

TEST(SkinRig, BaselinesMatchTheirDefinitions) {
  const SplineSet s = artwork();
  SkinRig rig = make_rig(s, detected(s));
  // One translation for every handle: all methods give the translated input.
  double T[24];
  identity(T, 4);
  for (int i = 0; i < 4; ++i) T[6 * i + 4] = 3, T[6 * i + 5] = -2;
  for (SkinMethod m :
       {SkinMethod::kNaiveAll, SkinMethod::kNaiveInterpolated, SkinMethod::kNaiveJacobian, SkinMethod::kFit}) {
    const double* X = rig.baseline(m, T);
    for (int k = 0; k < s.point_count(); ++k) {
      EXPECT_NEAR(X[2 * k], s.points[2 * k] + 3, 1e-9);
      EXPECT_NEAR(X[2 * k + 1], s.points[2 * k + 1] - 2, 1e-9);
    }
  }
  // Handle 0 rotated 90° about itself: the interpolated baseline moves handle points with their
  // anchor's blended transform, which is the naive result at the anchor plus M·(H − A).
  identity(T, 4);
  T[0] = 0, T[1] = 1, T[2] = -1, T[3] = 0, T[4] = 12 + 10, T[5] = 10 - 12;
  std::vector<double> all(rig.baseline(SkinMethod::kNaiveAll, T),
                          rig.baseline(SkinMethod::kNaiveAll, T) + s.points.size());
  const double* interp = rig.baseline(SkinMethod::kNaiveInterpolated, T);
  for (int k = 0; k < s.point_count(); k += 3) {  // anchors of the closed blob (count 18)
    if (k >= 18) break;
    EXPECT_NEAR(interp[2 * k], all[2 * k], 1e-12);
  }
  double w[4];
  shepard_weights(kHandles, 4, &s.points[0], 1, 2.0, w);  // anchor 0's weights
  const double hx = s.points[2], hy = s.points[3];        // its outgoing handle (point 1)
  const double mx = w[0] * (0 * hx - 1 * hy + 22) + (1 - w[0]) * hx;
  EXPECT_NEAR(interp[2], mx, 1e-9);
}

TEST(SkinRig, FlexibleRelaxNeverIncreasesTheEnergy) {
  const SplineSet s = artwork();
  std::vector<Continuity> kinds = detected(s);
  for (Continuity& k : kinds)
    if (k == Continuity::kC1) k = Continuity::kG1;  // let every smooth junction flex
  SkinRig rig = make_rig(s, kinds);
  std::mt19937 rng(3);
  int improved = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<double> T = random_pose(rng);
    const RelaxReport r = rig.relax(T.data());
    ASSERT_GE(r.energies.size(), 1u);
    for (size_t i = 1; i < r.energies.size(); ++i) EXPECT_LE(r.energies[i], r.energies[i - 1] * (1 + 1e-12));
    if (r.energies.back() < 0.999 * r.energies.front()) ++improved;
    // Tangents stay collinear (G1) with the rest turn, handles never flip.
    const double* X = rig.points().data();
    const int n = 18;
    for (int anchor = 0; anchor < n; anchor += 3) {
      if (kinds[anchor / 3] != Continuity::kG1) continue;
      const int in = (anchor + n - 1) % n, out = anchor + 1;
      const Vec2 a(X[2 * anchor] - X[2 * in], X[2 * anchor + 1] - X[2 * in + 1]);
      const Vec2 b(X[2 * out] - X[2 * anchor], X[2 * out + 1] - X[2 * anchor + 1]);
      const Vec2 ra(s.points[2 * anchor] - s.points[2 * in], s.points[2 * anchor + 1] - s.points[2 * in + 1]);
      const Vec2 rb(s.points[2 * out] - s.points[2 * anchor], s.points[2 * out + 1] - s.points[2 * anchor + 1]);
      const double rest_turn = std::atan2(ra.x() * rb.y() - ra.y() * rb.x(), ra.dot(rb));
      const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      EXPECT_NEAR(turn, rest_turn, 1e-7);
    }
  }
  EXPECT_GE(improved, 5);  // flexibility lowers the energy on most poses
}

TEST(SkinRig, LonePointsAndBadInput) {
  SplineSet s = artwork();
  s.start.push_back(s.point_count());
  s.count.push_back(1);
  s.closed.push_back(0);
  s.points.insert(s.points.end(), {30, 30});
  SkinRig rig = make_rig(s, detected(s));
  double T[24];
  identity(T, 4);
  for (int i = 0; i < 4; ++i) T[6 * i + 4] = 1;
  const double* X = rig.update(T);
  EXPECT_NEAR(X[2 * (s.point_count() - 1)], 31, 1e-9);

  SkinRig bad;
  EXPECT_NE(bad.setup(s, {}, 4, {}).find("continuity tags"), std::string::npos);
  EXPECT_NE(bad.setup(s, detected(s), 0, {}).find("at least one handle"), std::string::npos);
  ASSERT_EQ(bad.setup(s, detected(s), 4, {}), "");
  bad.use_shepard(kHandles, 2.0);
  bad.sample_weights()[3] = NAN;
  EXPECT_NE(bad.precompute().find("non-finite"), std::string::npos);
}
