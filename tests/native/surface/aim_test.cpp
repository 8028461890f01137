// The aimed end-to-end chord (aim.h) against what the surface says it must give: on a developable
// cylinder the straight line of the unrolled surface (its length in closed form, found in one shot);
// on a bump, where the strip's layout mis-aims it, lines re-aimed until they reach the end, whose
// paths are within 0.5% of the exact distance; where the line meets a hole, nothing changes.
#include "surface/aim.h"
#include "surface/geodesic.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace splinekit::surface {
namespace {

using testing::Arrays;

MeshPoint centroid(int face) { return {face, Vec2(1.0 / 3, 1.0 / 3)}; }

// Consecutive faces share an edge and no face comes twice.
void expect_strip(const TriMesh& mesh, const std::vector<int>& strip) {
  for (size_t i = 0; i + 1 < strip.size(); ++i)
    EXPECT_GE(edge_to(mesh, strip[i], strip[i + 1]), 0) << "faces " << i << ", " << i + 1;
  std::vector<int> sorted = strip;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a face twice";
}

// The dual graph's strip from a to b, laid out and its funnel path found, in `s`.
void begin_on_dual_strip(GeodesicSolver& solver, Straightener& s, const MeshPoint& a, const MeshPoint& b) {
  std::vector<int> strip;
  ASSERT_TRUE(solver.initial_strip(a, b, strip, nullptr, SearchGraph::kDual));
  s.begin(a, b, strip);
}

TEST(Aim, OnACylinderTheLineOfTheUnrolledSurfaceInOneShot) {
  // 96 sides of radius 1, height 2 in 64 rows: flat faces, every vertex of angle sum 2π, so the
  // unrolled surface is a plane strip of width 96 sides; a geodesic there is a straight line.
  const int around = 96, up = 64;
  const TriMesh mesh = testing::build(testing::cylinder(around, up, 1, 2));
  const double side = 2 * std::sin(kPi / around), row = 2.0 / up;
  // Unrolled: the vertex at angle 2πi/96 and height z at (i * side, z); a face's centroid is its
  // corners' mean there.
  auto unrolled = [&](int face) {
    Vec2 sum = Vec2::Zero();
    double first = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec3& x = mesh.positions[mesh.triangles[face][k]];
      double i = std::atan2(x.y(), x.x()) * around / (2 * kPi);
      if (k == 0) first = i;
      if (i < first - around / 2.0) i += around;  // (across the seam: keep the face's corners together)
      if (i > first + around / 2.0) i -= around;
      sum += Vec2(i * side, x.z());
    }
    return Vec2(sum / 3);
  };
  GeodesicSolver solver(mesh);
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  // Faces 27 sides apart round the cylinder and 48 rows up.
  auto at = [&](double i, double z) {
    return testing::point_at(mesh, Vec3(std::cos(2 * kPi * i / around), std::sin(2 * kPi * i / around), z)).face;
  };
  const int a = at(3.4, 8.3 * row), b = at(30.6, 56.7 * row);
  begin_on_dual_strip(solver, s, centroid(a), centroid(b));
  const double dual_length = s.length();
  PathStats stats;
  ASSERT_TRUE(s.take_aim(&stats));
  EXPECT_EQ(stats.shots, 1);
  EXPECT_EQ(stats.aimed, 1);
  const double expected = (unrolled(b) - unrolled(a)).norm();
  EXPECT_NEAR(s.length(), expected, 1e-9 * expected);
  EXPECT_LT(s.length(), dual_length);
  EXPECT_EQ(s.apices().size(), 2u) << "the line bends nowhere";
  expect_strip(mesh, s.strip());
  EXPECT_FALSE(s.pass()) << "no reflex vertex left";
}

TEST(Aim, OnABumpReAimedUntilItReachesTheEnd) {
  // A smooth bump (height 0.2, width ~0.2) on a jittered grid: not developable, so a strip that goes
  // round its flank lays the end point off where the line across the flank arrives.
  Arrays arrays = testing::planar_grid(80, 1, 0.2);
  for (size_t v = 0; v < arrays.positions.size() / 3; ++v) {
    const double x = arrays.positions[3 * v] - 0.5, y = arrays.positions[3 * v + 1] - 0.5;
    arrays.positions[3 * v + 2] = 0.2 * std::exp(-(x * x + y * y) / 0.04);
  }
  const TriMesh mesh = testing::build(arrays);
  reference::ExactGeodesic exact = testing::exact_geodesic(mesh);
  GeodesicSolver solver(mesh);
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> face(0, static_cast<int>(mesh.triangles.size()) - 1);
  auto near_vertex = [&](std::mt19937& r) { return MeshPoint{face(r), Vec2(0.002, 0.001)}; };
  int aimed = 0, re_aimed = 0, pairs = 0;
  for (int k = 0; k < 40; ++k) {
    // Points inside faces, next to a vertex each (the exact distance is the vertices' up to `slack`).
    const MeshPoint a = near_vertex(rng), b = near_vertex(rng);
    const int va = mesh.triangles[a.face][0], vb = mesh.triangles[b.face][0];
    if ((mesh.positions[va] - mesh.positions[vb]).norm() < 0.4) continue;
    const double slack =
        (eval_position(mesh, a) - mesh.positions[va]).norm() + (eval_position(mesh, b) - mesh.positions[vb]).norm();
    ++pairs;
    begin_on_dual_strip(solver, s, a, b);
    const double before = s.length();
    PathStats stats;
    if (!s.take_aim(&stats)) continue;
    ++aimed;
    re_aimed += stats.shots > 1;
    EXPECT_LT(s.length(), before);
    expect_strip(mesh, s.strip());
    while (s.pass()) {
    }
    const double d = exact.distances(va)[vb];
    EXPECT_GE(s.length(), d - slack) << "pair " << va << "-" << vb;
    EXPECT_LE(s.length(), d * 1.005 + slack) << "pair " << va << "-" << vb;
  }
  EXPECT_GE(pairs, 20);
  EXPECT_GE(aimed, pairs / 2) << "most lines reach the end";
  EXPECT_GE(re_aimed, pairs / 3) << "many only after re-aiming";
}

TEST(Aim, ALineThroughAHoleChangesNothing) {
  // A grid with a square hole in the middle: the dual strip goes round it, the line from end to end
  // runs into it and stops at its boundary.
  Arrays grid = testing::planar_grid(40, 1, 0.2);
  Arrays holed;
  holed.positions = grid.positions;
  for (size_t t = 0; t < grid.triangles.size(); t += 3) {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      c += Vec3(grid.positions[3 * grid.triangles[t + k]], grid.positions[3 * grid.triangles[t + k] + 1], 0);
    c /= 3;
    if (std::abs(c.x() - 0.5) < 0.2 && std::abs(c.y() - 0.5) < 0.2) continue;
    holed.triangles.insert(holed.triangles.end(), grid.triangles.begin() + t, grid.triangles.begin() + t + 3);
  }
  const TriMesh mesh = testing::build(holed);
  const MeshPoint a = testing::point_at(mesh, Vec3(0.1, 0.48, 0)), b = testing::point_at(mesh, Vec3(0.9, 0.52, 0));
  GeodesicSolver solver(mesh);
  std::vector<int> marks(mesh.triangles.size(), -1);
  Straightener s(mesh, marks);
  begin_on_dual_strip(solver, s, a, b);
  const std::vector<int> strip = s.strip();
  const double length = s.length();
  PathStats stats;
  EXPECT_FALSE(s.take_aim(&stats));
  EXPECT_GE(stats.shots, 1);
  EXPECT_EQ(stats.aimed, 0);
  EXPECT_EQ(s.strip(), strip);
  EXPECT_EQ(s.length(), length);
  // And a whole path with aiming is the one without.
  GeodesicPath with, without;
  solver.shortest_path(a, b, with, nullptr, SearchGraph::kDual);
  ShortestPathOptions options;
  options.aim_shots = 0;
  GeodesicSolver plain(mesh, options);
  plain.shortest_path(a, b, without, nullptr, SearchGraph::kDual);
  EXPECT_EQ(with.strip, without.strip);
  EXPECT_NEAR(path_length(mesh, with), path_length(mesh, without), 1e-12);
}

}  // namespace
}  // namespace splinekit::surface
