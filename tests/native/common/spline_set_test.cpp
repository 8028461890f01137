// SplineSet validation and batch queries.
#include "common/spline_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/bezier.h"

using namespace splinekit;

namespace {
SplineSet two_splines() {
  SplineSet s;
  // Open line-cubic (4 points) then a closed triangle of 3 line-cubics (9 points).
  s.points = {0, 0, 1, 1, 2, 2, 3, 3};
  const double tri[4][2] = {{10, 0}, {13, 0}, {10, 3}, {10, 0}};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      s.points.push_back(tri[k][0] + i / 3.0 * (tri[k + 1][0] - tri[k][0]));
      s.points.push_back(tri[k][1] + i / 3.0 * (tri[k + 1][1] - tri[k][1]));
    }
  s.start = {0, 4};
  s.count = {4, 9};
  s.closed = {0, 1};
  return s;
}
}  // namespace

TEST(SplineSet, ValidSetCountsSegmentsAndJunctions) {
  const SplineSet s = two_splines();
  EXPECT_EQ(validate(s), "");
  EXPECT_EQ(total_segments(s), 4);
  EXPECT_EQ(total_junctions(s), 3);
}

TEST(SplineSet, ValidationNamesTheProblem) {
  SplineSet s = two_splines();
  s.count[1] = 8;
  EXPECT_NE(validate(s).find("closed spline needs 3n"), std::string::npos);
  s = two_splines();
  s.count[0] = 5;
  EXPECT_NE(validate(s).find("open spline needs 3n+1"), std::string::npos);
  s = two_splines();
  s.start[1] = 10;
  EXPECT_NE(validate(s).find("outside"), std::string::npos);
  s = two_splines();
  s.points[7] = NAN;
  EXPECT_NE(validate(s).find("point 3 has a non-finite"), std::string::npos);
  s = two_splines();
  s.points[0] = INFINITY;
  EXPECT_NE(validate(s).find("non-finite"), std::string::npos);
}

TEST(SplineSet, BoundsSampleAndClassify) {
  const SplineSet s = two_splines();
  double b[8];
  spline_set_bounds(s, b);
  EXPECT_DOUBLE_EQ(b[2], 3);
  EXPECT_DOUBLE_EQ(b[4], 10);
  EXPECT_DOUBLE_EQ(b[6], 13);
  EXPECT_DOUBLE_EQ(b[7], 3);
  std::vector<double> samples(2 * 3 * 4);
  spline_set_sample(s, 3, samples.data());
  EXPECT_DOUBLE_EQ(samples[2], 1.5);    // midpoint of the line
  EXPECT_DOUBLE_EQ(samples[6], 10);     // triangle starts at (10,0)
  EXPECT_NEAR(samples[22], 10, 1e-14);  // closing segment ends back at (10,0)
  EXPECT_NEAR(samples[23], 0, 1e-14);
  JunctionInfo j[3];
  spline_set_classify(s, {}, j);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(j[k].kind, Continuity::kC0);
  // Triangle corners at (10,0): closing edge comes in going down (0,-1), leaves going +x: left turn.
  EXPECT_NEAR(j[0].angle, kPi / 2, 1e-14);
  EXPECT_NEAR(j[1].angle, 3 * kPi / 4, 1e-14);
}
