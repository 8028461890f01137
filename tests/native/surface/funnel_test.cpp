// The funnel (funnel.h) against closed forms: inside a flat strip that holds the segment between
// its ends the path is that segment and crosses each edge where the segment does; turning angles
// and the apices where the path goes straight on.
#include "surface/funnel.h"
#include "surface/geodesic.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace splinekit::surface {
namespace {

Apex at(double x, double y, int vertex = -1) { return {Vec2(x, y), vertex, 0, 0}; }

TEST(Funnel, IsTheSegmentInAFlatStripThatHoldsIt) {
  const TriMesh mesh = testing::build(testing::planar_grid(8, 1, 0.2));
  const MeshPoint a = testing::point_at(mesh, {0.07, 0.11, 0}), b = testing::point_at(mesh, {0.93, 0.71, 0});
  GeodesicSolver solver(mesh);
  GeodesicPath path;
  ASSERT_TRUE(solver.shortest_path(a, b, path));
  ASSERT_GT(path.strip.size(), 8u);
  UnfoldedStrip u;
  unfold_strip(mesh, path.strip, u);
  const int last = static_cast<int>(path.strip.size()) - 1;
  std::vector<Apex> apices;
  funnel(u, u.map(0, path.start), u.map(last, path.end), apices);
  const Vec3 pa = eval_position(mesh, a), pb = eval_position(mesh, b);
  ASSERT_EQ(apices.size(), 2u);
  EXPECT_NEAR(polyline_length(apices), (pb - pa).norm(), 1e-12);
  // Each crossing, read on the edge's end points in space, lies on the segment, at the arc length
  // the funnel reports.
  std::vector<double> lerps, arc;
  crossings(u, apices, lerps, arc);
  ASSERT_EQ(lerps.size(), path.strip.size() - 1);
  ASSERT_EQ(arc.size(), path.strip.size() + 1);
  for (size_t i = 0; i < lerps.size(); ++i) {
    const Vec3 &r = mesh.positions[u.portals[i].right_vertex], &l = mesh.positions[u.portals[i].left_vertex];
    const Vec3 x = r + lerps[i] * (l - r);
    EXPECT_NEAR((x - pa).cross(pb - pa).norm() / (pb - pa).norm(), 0, 1e-12) << "crossing " << i;
    EXPECT_NEAR(arc[i + 1], (x - pa).norm(), 1e-12) << "crossing " << i;
  }
  EXPECT_NEAR(arc.back(), (pb - pa).norm(), 1e-12);
}

TEST(Funnel, TurnAtIsTheAngleBetweenTheSegments) {
  for (double t : {0.0, 0.3, 1.2, 2.5, 3.1}) {
    const std::vector<Apex> apices = {at(0, 0), at(1, 0, 4), at(1 + 2 * std::cos(t), 2 * std::sin(t))};
    EXPECT_NEAR(turn_at(apices, 1), t, 1e-12);
    const std::vector<Apex> mirrored = {at(0, 0), at(1, 0, 4), at(1 + 2 * std::cos(t), -2 * std::sin(t))};
    EXPECT_NEAR(turn_at(mirrored, 1), t, 1e-12);
  }
  EXPECT_EQ(turn_at({at(0, 0), at(1, 1)}, 0), 0);  // (the ends do not turn)
}

TEST(Funnel, DropStraightKeepsRealBendsAndReversals) {
  // A vertex on the line between its neighbours goes; a bend and a turn back stay.
  std::vector<Apex> apices = {at(0, 0), at(1, 0, 5), at(2, 0, 6), at(2, 1)};
  drop_straight(apices);
  ASSERT_EQ(apices.size(), 3u);
  EXPECT_EQ(apices[1].vertex, 6);
  apices = {at(0, 0), at(1, 0, 5), at(0.5, 0)};
  drop_straight(apices);
  EXPECT_EQ(apices.size(), 3u);
}

}  // namespace
}  // namespace splinekit::surface
