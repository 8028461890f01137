// The active window: clamped on open curves, wrapping on closed ones, the whole curve when larger.
#include "edit/active_window.h"

#include <gtest/gtest.h>

using namespace splinekit::edit;

TEST(ActiveWindow, ClampsAtAnOpenCurvesEnds) {
  ActiveWindow w;
  ASSERT_EQ(resolve_window(10, false, 2, 5, 4, w), "");
  EXPECT_EQ(w.left, 2);   // only points 0 and 1 lie to the left
  EXPECT_EQ(w.right, 4);  // asymmetric, as asked
  EXPECT_EQ(w.index(0), 0);
  EXPECT_EQ(w.index(w.left), 2);
  EXPECT_EQ(w.index(w.size() - 1), 6);
  ASSERT_EQ(resolve_window(10, false, 8, 3, 100, w), "");
  EXPECT_EQ(w.left, 3);
  EXPECT_EQ(w.right, 1);
  // Larger than the curve: the whole curve.
  ASSERT_EQ(resolve_window(10, false, 4, 50, 50, w), "");
  EXPECT_EQ(w.index(0), 0);
  EXPECT_EQ(w.index(w.size() - 1), 9);
}

TEST(ActiveWindow, WrapsAcrossAClosedCurvesSeam) {
  ActiveWindow w;
  ASSERT_EQ(resolve_window(10, true, 1, 3, 2, w), "");
  EXPECT_EQ(w.left, 3);
  EXPECT_EQ(w.index(0), 8);
  EXPECT_EQ(w.index(1), 9);
  EXPECT_EQ(w.index(2), 0);
  EXPECT_EQ(w.index(3), 1);
  EXPECT_EQ(w.index(5), 3);
}

TEST(ActiveWindow, CoversAClosedLoopWithBothEndsAtOnePoint) {
  ActiveWindow w;
  ASSERT_EQ(resolve_window(10, true, 0, 20, 20, w), "");
  EXPECT_EQ(w.left + w.right, 10);
  EXPECT_EQ(w.left, 5);
  EXPECT_EQ(w.index(0), w.index(w.size() - 1));
  EXPECT_EQ(w.index(0), 5);
  ASSERT_EQ(resolve_window(10, true, 0, 3, 9, w), "");  // 12 >= 10: split 3:9 → 3 (rounded 2.5) and 7
  EXPECT_EQ(w.left + w.right, 10);
  EXPECT_EQ(w.index(0), w.index(w.size() - 1));
}

TEST(ActiveWindow, RejectsOutOfRangeAndNegative) {
  ActiveWindow w;
  EXPECT_NE(resolve_window(10, false, 10, 1, 1, w).find("control point 10 is out of range"), std::string::npos);
  EXPECT_NE(resolve_window(10, false, -1, 1, 1, w).find("out of range"), std::string::npos);
  EXPECT_NE(resolve_window(10, true, 3, -1, 1, w).find("negative"), std::string::npos);
}
