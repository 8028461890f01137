// Point location on its own: barycentric coordinates and nearest points of one triangle against
// closed forms, the grid's answers on a two-triangle square, on grid meshes against brute force,
// and across the notch of a non-convex mesh.
#include "skin/point_location.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "test_meshes.h"

using namespace splinekit::skin;
using test_meshes::grid_mesh;
using test_meshes::Mesh;

namespace {

class LocationOnMeshes : public ::testing::TestWithParam<bool> {
 protected:
  Mesh mesh = grid_mesh(16, GetParam());
};

}  // namespace

TEST(PointLocation, BarycentricCoordinatesReproduceThePointInEitherOrientation) {
  const std::vector<double> V = {0, 0, 4, 0, 0, 2};
  for (const std::vector<int32_t>& F : {std::vector<int32_t>{0, 1, 2}, std::vector<int32_t>{0, 2, 1}}) {
    const MeshView2 m{V.data(), 3, F.data(), 1};
    double b[3];
    triangle_barycentric(m, 0, 2, 0.5, b);
    // (2, 0.5) = 0.25·(0,0) + 0.5·(4,0) + 0.25·(0,2), in the order the triangle lists them.
    const double expected[3] = {0.25, F[1] == 1 ? 0.5 : 0.25, F[1] == 1 ? 0.25 : 0.5};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], expected[k], 1e-15);
    // Outside: (−2, 3) gets coordinates, one of them negative, that still sum to 1 and reproduce it.
    triangle_barycentric(m, 0, -2, 3, b);
    double x = 0, y = 0;
    for (int k = 0; k < 3; ++k) x += b[k] * V[2 * F[k]], y += b[k] * V[2 * F[k] + 1];
    EXPECT_NEAR(b[0] + b[1] + b[2], 1, 1e-15);
    EXPECT_NEAR(x, -2, 1e-14);
    EXPECT_NEAR(y, 3, 1e-14);
    EXPECT_LT(std::min({b[0], b[1], b[2]}), 0);
  }
}

TEST(PointLocation, NearestPointOnATriangleMatchesClosedForms) {
  const std::vector<double> V = {0, 0, 1, 0, 0, 1};
  const std::vector<int32_t> F = {0, 1, 2};
  const MeshView2 m{V.data(), 3, F.data(), 1};
  double b[3];
  // Inside: distance 0, the point's own coordinates.
  EXPECT_EQ(nearest_on_triangle(m, 0, 0.2, 0.3, b), 0.0);
  EXPECT_NEAR(b[1], 0.2, 1e-15);
  EXPECT_NEAR(b[2], 0.3, 1e-15);
  // Beyond the hypotenuse: the foot of the perpendicular (0.5, 0.5), distance² 2·1.5² = 4.5.
  EXPECT_NEAR(nearest_on_triangle(m, 0, 2, 2, b), 4.5, 1e-14);
  EXPECT_NEAR(b[0], 0, 1e-15);
  EXPECT_NEAR(b[1], 0.5, 1e-15);
  EXPECT_NEAR(b[2], 0.5, 1e-15);
  // Behind a corner: the corner itself.
  EXPECT_NEAR(nearest_on_triangle(m, 0, -1, -1, b), 2, 1e-15);
  EXPECT_NEAR(b[0], 1, 1e-15);
  // Below an edge: straight down onto it.
  EXPECT_NEAR(nearest_on_triangle(m, 0, 0.25, -3, b), 9, 1e-14);
  EXPECT_NEAR(b[0], 0.75, 1e-15);
  EXPECT_NEAR(b[1], 0.25, 1e-15);
  EXPECT_NEAR(b[2], 0, 1e-15);
}

TEST(PointLocation, GridOfASquareLocatesInsideAndOutside) {
  // The square [0,2]² split along its diagonal (0,0)–(2,2).
  const std::vector<double> V = {0, 0, 2, 0, 2, 2, 0, 2};
  const std::vector<int32_t> F = {0, 1, 2, 0, 2, 3};
  const MeshView2 m{V.data(), 4, F.data(), 2};
  TriangleGrid grid;
  build_triangle_grid(m, grid);
  EXPECT_EQ(grid.start.size(), size_t(grid.nx) * grid.ny + 1);
  EXPECT_EQ(int(grid.items.size()), grid.start.back());
  double b[3];
  EXPECT_EQ(locate_point(grid, m, 1.5, 0.5, b), 0);  // below the diagonal
  EXPECT_NEAR(b[0] * 0 + b[1] * 2 + b[2] * 2, 1.5, 1e-14);
  EXPECT_EQ(locate_point(grid, m, 0.5, 1.5, b), 1);  // above it
  EXPECT_NEAR(b[0] * 0 + b[1] * 2 + b[2] * 0, 0.5, 1e-14);
  // Outside, right of the square at height 1.5: the nearest point is (2, 1.5) on triangle 0's edge.
  EXPECT_EQ(locate_point(grid, m, 5, 1.5, b), 0);
  EXPECT_NEAR(b[0], 0, 1e-15);
  EXPECT_NEAR(b[1], 0.25, 1e-15);
  EXPECT_NEAR(b[2], 0.75, 1e-15);
  // Interpolating x and y as vertex values gives back the point inside, the nearest point outside.
  const std::vector<double> W = V;  // #V by 2: "weights" equal to the coordinates
  const std::vector<double> P = {0.3, 1.7, 1.1, 0.2, -4, -1, 3, 3};
  std::vector<double> out(P.size());
  locate_and_interpolate(grid, m, W.data(), 2, P.data(), 4, out.data());
  const std::vector<double> expected = {0.3, 1.7, 1.1, 0.2, 0, 0, 2, 2};
  for (size_t k = 0; k < out.size(); ++k) EXPECT_NEAR(out[k], expected[k], 1e-14) << k;
}

TEST_P(LocationOnMeshes, LocationAgreesWithBruteForceInsideAndOutside) {
  TriangleGrid grid;
  build_triangle_grid(mesh.view(), grid);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> inside(0, 1), around(-0.7, 1.7);
  auto point_of = [&](int t, const double* b, int a) {
    return b[0] * mesh.V[2 * mesh.F[3 * t] + a] + b[1] * mesh.V[2 * mesh.F[3 * t + 1] + a] +
           b[2] * mesh.V[2 * mesh.F[3 * t + 2] + a];
  };
  for (int k = 0; k < 2000; ++k) {
    const double x = inside(rng), y = inside(rng);
    double b[3];
    const int t = locate_point(grid, mesh.view(), x, y, b);
    ASSERT_GE(t, 0);
    EXPECT_GE(std::min({b[0], b[1], b[2]}), 0.0);
    EXPECT_NEAR(b[0] + b[1] + b[2], 1.0, 1e-15);
    EXPECT_NEAR(point_of(t, b, 0), x, 1e-12);
    EXPECT_NEAR(point_of(t, b, 1), y, 1e-12);
  }
  // Outside the unit square the nearest point of the mesh is the clamp of the point to the square.
  for (int k = 0; k < 2000; ++k) {
    const double x = around(rng), y = around(rng);
    double b[3];
    const int t = locate_point(grid, mesh.view(), x, y, b);
    ASSERT_GE(t, 0);
    EXPECT_GE(std::min({b[0], b[1], b[2]}), 0.0);
    EXPECT_NEAR(point_of(t, b, 0), std::clamp(x, 0.0, 1.0), 1e-12);
    EXPECT_NEAR(point_of(t, b, 1), std::clamp(y, 0.0, 1.0), 1e-12);
  }
  // Far away, too.
  double b[3];
  const int t = locate_point(grid, mesh.view(), 1e6, -3e5, b);
  EXPECT_NEAR(point_of(t, b, 0), 1.0, 1e-12);
  EXPECT_NEAR(point_of(t, b, 1), 0.0, 1e-12);
}

TEST(PointLocation, LocationOfANonConvexMeshFindsTheNearestTriangleAcrossTheNotch) {
  // An L shape: the unit square minus its upper-right quarter (grid 4x4 without the quarter).
  Mesh m = grid_mesh(4, false);
  std::vector<int32_t> F;
  for (int t = 0; t < m.nf(); ++t) {
    double cx = 0, cy = 0;
    for (int k = 0; k < 3; ++k) cx += m.V[2 * m.F[3 * t + k]] / 3, cy += m.V[2 * m.F[3 * t + k] + 1] / 3;
    if (!(cx > 0.5 && cy > 0.5)) F.insert(F.end(), m.F.begin() + 3 * t, m.F.begin() + 3 * t + 3);
  }
  // Drop the vertices strictly inside the removed quarter (they belong to no triangle).
  std::vector<int> remap(m.nv(), -1);
  std::vector<double> V;
  for (int32_t& v : F) {
    if (remap[v] < 0) remap[v] = int(V.size() / 2), V.push_back(m.V[2 * v]), V.push_back(m.V[2 * v + 1]);
    v = remap[v];
  }
  m.V = V;
  m.F = F;
  TriangleGrid grid;
  build_triangle_grid(m.view(), grid);
  double b[3];
  const int t = locate_point(grid, m.view(), 0.9, 0.6, b);  // in the notch, 0.1 above the lower arm
  double x = 0, y = 0;
  for (int k = 0; k < 3; ++k) x += b[k] * m.V[2 * m.F[3 * t + k]], y += b[k] * m.V[2 * m.F[3 * t + k] + 1];
  EXPECT_NEAR(x, 0.9, 1e-12);
  EXPECT_NEAR(y, 0.5, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(RegularAndIrregular, LocationOnMeshes, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "Irregular" : "Regular";
                         });
