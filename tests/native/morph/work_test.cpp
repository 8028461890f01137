#include "morph/work.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_shapes.h"

using namespace splinekit;
using namespace splinekit::morph;

TEST(MorphWork, ClosedForms) {
  WorkOptions o;
  o.stretching = 2;
  o.bending = 3;
  o.kinking = 5;
  o.kink_exponent = 2;
  EXPECT_DOUBLE_EQ(stretching_work(1, 3, o), 2 * 4.0 / 4.0);         // eq. 3
  EXPECT_DOUBLE_EQ(bending_work(0.5, 1.5, 1, 3, o), 3 * 1.0 / 4.0);  // eq. 4
  EXPECT_DOUBLE_EQ(kinking_work(0.25, -0.25, o), 5 * 0.25);          // eq. 5: 5 |−0.5|²
  EXPECT_EQ(stretching_work(0, 0, o), 0);                            // point to point
  EXPECT_DOUBLE_EQ(stretching_work(2, 0, o), 2 * 2.0);               // a segment shrinks to a point: c_s L
  EXPECT_EQ(validate(WorkOptions{}), "");
  EXPECT_NE(validate(WorkOptions{-1, 1, 1, 1}), "");
  EXPECT_NE(validate(WorkOptions{1, 1, 1, 0}), "");
  EXPECT_NE(validate(WorkOptions{1, NAN, 1, 1}), "");
}

TEST(MorphWork, BendingOfArcsAndLines) {
  // A quarter circle arc turns its tangent by π/2; a straight segment by 0; reversed: −π/2.
  const auto c = test::circle(0, 0, 1, 4);
  const double arc[8] = {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]};
  EXPECT_NEAR(segment_bending(arc), kPi / 2, 1e-12);
  const double back[8] = {c[6], c[7], c[4], c[5], c[2], c[3], c[0], c[1]};
  EXPECT_NEAR(segment_bending(back), -kPi / 2, 1e-12);
  const double line[8] = {0, 0, 1, 1, 2, 2, 3, 3};
  EXPECT_EQ(segment_bending(line), 0);
  // Handles on their anchors (zero end derivatives) still measure the turn of the curve.
  const double cusp_free[8] = {0, 0, 0, 0, 1, 0, 1, 1};
  EXPECT_NEAR(segment_bending(cusp_free), kPi / 2, 1e-9);
}

TEST(MorphWork, MeasureIsInvariantUnderRigidMotionAndScalesLengthsOnly) {
  const auto d = test::d_shape(2);
  KnotChain c, moved, scaled;
  ASSERT_EQ(chain_from_bezier(d.data(), 9, true, {}, c), "");
  const double co = std::cos(0.7), si = std::sin(0.7);
  const auto dm = test::transformed(d, co, si, -si, co, 5, -3);
  const auto ds = test::transformed(d, 3, 0, 0, 3, 0, 0);
  ASSERT_EQ(chain_from_bezier(dm.data(), 9, true, {}, moved), "");
  ASSERT_EQ(chain_from_bezier(ds.data(), 9, true, {}, scaled), "");
  const ChainMeasure m = measure(c, 1), mm = measure(moved, 1), ms = measure(scaled, 1);
  for (size_t k = 0; k < m.length.size(); ++k) {
    EXPECT_NEAR(mm.length[k], m.length[k], 1e-9);
    EXPECT_NEAR(mm.bending[k], m.bending[k], 1e-9);
    EXPECT_NEAR(ms.length[k], 3 * m.length[k], 1e-9);
    EXPECT_NEAR(ms.bending[k], m.bending[k], 1e-9);
  }
  // Kinks: the D's two corners turn by +π/2 (counter-clockwise), the smooth join by 0.
  EXPECT_NEAR(m.kink[0], kPi / 2, 1e-9);
  EXPECT_EQ(m.kink[1], 0);
  EXPECT_NEAR(m.kink[2], kPi / 2, 1e-9);
  for (size_t a = 0; a < m.kink.size(); ++a) EXPECT_NEAR(mm.kink[a], m.kink[a], 1e-9);
}
