// Junction classification: constructed junctions of each kind, tolerances, degenerate handles.
#include "common/continuity.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/geometry.h"
#include "common/spline_set.h"

using namespace splinekit;

namespace {

JunctionInfo classify(double ax, double ay, double bx, double by, ContinuityOptions o = {}) {
  // Anchor at (5,5); incoming handle at P - a, outgoing at P + b; far points further along.
  const double in_far[2] = {5 - 2 * ax - 1, 5 - 2 * ay}, h_in[2] = {5 - ax, 5 - ay}, p[2] = {5, 5};
  const double h_out[2] = {5 + bx, 5 + by}, out_far[2] = {5 + 2 * bx + 1, 5 + 2 * by};
  return classify_junction(in_far, h_in, p, h_out, out_far, o);
}

}  // namespace

TEST(Continuity, C1WhenTangentVectorsAreEqual) {
  const JunctionInfo j = classify(1, 2, 1, 2);
  EXPECT_EQ(j.kind, Continuity::kC1);
  EXPECT_NEAR(j.ratio, 1.0, 1e-15);
  EXPECT_NEAR(j.angle, 0.0, 1e-15);
}

TEST(Continuity, G1WithItsRatio) {
  const JunctionInfo j = classify(1, 2, 2.5, 5);
  EXPECT_EQ(j.kind, Continuity::kG1);
  EXPECT_NEAR(j.ratio, 2.5, 1e-14);
}

TEST(Continuity, CornerIsC0WithSignedAngle) {
  JunctionInfo j = classify(1, 0, 0, 1);  // turning left by 90 degrees
  EXPECT_EQ(j.kind, Continuity::kC0);
  EXPECT_NEAR(j.angle, kPi / 2, 1e-14);
  j = classify(1, 0, 0, -2);
  EXPECT_EQ(j.kind, Continuity::kC0);
  EXPECT_NEAR(j.angle, -kPi / 2, 1e-14);
  // Folding back (a cusp) is a corner, not G1, even though the handles are collinear.
  j = classify(1, 0, -1, 0);
  EXPECT_EQ(j.kind, Continuity::kC0);
  EXPECT_NEAR(std::abs(j.angle), kPi, 1e-14);
}

TEST(Continuity, TolerancesDecideNearlySmoothJunctions) {
  ContinuityOptions o;
  o.angle_tolerance = 1e-3;
  // sin(angle) = 5e-4: smooth within tolerance.
  EXPECT_EQ(classify(1, 0, std::cos(5e-4), std::sin(5e-4), o).kind, Continuity::kC1);
  // sin(angle) = 2e-3: a (slight) corner.
  EXPECT_EQ(classify(1, 0, std::cos(2e-3), std::sin(2e-3), o).kind, Continuity::kC0);
  // Ratio 1.0005 is C1 under ratio_tolerance 1e-3, 1.01 is G1.
  EXPECT_EQ(classify(1, 0, 1.0005, 0, o).kind, Continuity::kC1);
  EXPECT_EQ(classify(1, 0, 1.01, 0, o).kind, Continuity::kG1);
}

TEST(Continuity, DegenerateHandleIsACornerWithTheNextPointsDirection) {
  // Incoming handle on the anchor: direction comes from in_far; ratio is undefined (0).
  const JunctionInfo j = classify(0, 0, 1, 0);
  EXPECT_EQ(j.kind, Continuity::kC0);
  EXPECT_EQ(j.ratio, 0.0);
  EXPECT_NEAR(j.angle, 0.0, 1e-14);  // in_far lies at (4,5): the same direction as the outgoing handle
  // Length tolerance scales with drawing size: a 1e-4 handle is degenerate in a 1000-unit drawing.
  const ContinuityOptions big = continuity_options_for_size(1000.0, 1e-6);
  EXPECT_NEAR(big.length_tolerance, 1e-3, 1e-18);
  EXPECT_EQ(classify(1e-4, 0, 1e-4, 0, big).kind, Continuity::kC0);
  EXPECT_EQ(classify(1e-4, 0, 1e-4, 0).kind, Continuity::kC1);
}

TEST(Continuity, JunctionOrderOfOpenAndClosedSplines) {
  // Open spline of 3 segments: junctions at anchors 3 and 6. The first is smooth, the second a corner.
  const double open[20] = {0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 5, 0, 6, 0, 6, 1, 6, 2, 6, 3};
  EXPECT_EQ(spline_junction_count(10, false), 2);
  JunctionInfo out[4];
  classify_spline(open, 10, false, {}, out);
  EXPECT_EQ(out[0].kind, Continuity::kC1);
  EXPECT_EQ(out[1].kind, Continuity::kC0);
  EXPECT_NEAR(out[1].angle, kPi / 2, 1e-14);
  // Closed square of 4 line-cubics: 4 corners at anchors 0, 3, 6, 9, all turning +90 degrees.
  double sq[24];
  const double corners[5][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {0, 0}};
  for (int s = 0; s < 4; ++s)
    for (int k = 0; k < 3; ++k) {
      sq[6 * s + 2 * k] = corners[s][0] + k / 3.0 * (corners[s + 1][0] - corners[s][0]);
      sq[6 * s + 2 * k + 1] = corners[s][1] + k / 3.0 * (corners[s + 1][1] - corners[s][1]);
    }
  EXPECT_EQ(spline_junction_count(12, true), 4);
  classify_spline(sq, 12, true, {}, out);
  for (int j = 0; j < 4; ++j) {
    EXPECT_EQ(out[j].kind, Continuity::kC0);
    EXPECT_NEAR(out[j].angle, kPi / 2, 1e-14) << j;
  }
}
