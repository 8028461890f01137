// The coarse guide of long paths (coarse_guide.h) on a coil: a tube wound into 8 turns, where the
// greedy search's strip between far points keeps to the side of the tube it started on and the
// straightening sweeps the band between. The guide here is the coil's own grid thinned (every 4th ring,
// every 2nd vertex round it: an eighth of the faces, on the coil's vertices), as a decimation that
// keeps a subset of the vertices would give.
#include "surface/coarse_guide.h"
#include "../reference/exact_geodesic.h"
#include "surface/geodesic.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace splinekit::surface {
namespace {

constexpr int kAlong = 800, kAround = 16;

const TriMesh& coil() {
  static const TriMesh mesh = testing::build(testing::coil(kAlong, kAround));  // 25,600 triangles
  return mesh;
}

const TriMesh& knot() {
  static const TriMesh mesh = testing::build(testing::knot_tube(1200, 12));  // 28,824 triangles, about 9:1
  return mesh;
}

void set_guide(GeodesicSolver& solver,
               const std::vector<int>& triangles = testing::thinned_tube(kAlong, kAround, false, 4, 2)) {
  std::string error;
  ASSERT_EQ(solver.set_coarse_guide(triangles.data(), static_cast<int>(triangles.size() / 3), error), MeshStatus::kOk)
      << error;
}

// Between vertices far apart on a tube: the guided paths are real paths (adjacent faces, the given
// ends), with `exact`, never shorter than the exact distance and within 5% of it (locally shortest
// paths, as curve tracing asks for: on a coil a few lie along another side of the tube than the
// shortest), in total no longer than the greedy strips' straightened but for `slack`, with fewer flips
// and a search a fraction as large. `walks`: whether the strip walks the guide's path (long thin
// faces) or descends towards it.
void expect_guided_paths_follow(const TriMesh& mesh, const std::vector<int>& guide, bool walks, bool exact,
                                double slack) {
  GeodesicSolver guided(mesh), plain(mesh);
  set_guide(guided, guide);
  ASSERT_NE(guided.coarse_guide(), nullptr);
  EXPECT_EQ(guided.coarse_guide()->coarse().triangles.size(), guide.size() / 3);
  EXPECT_EQ(guided.coarse_guide()->walks(), walks);
  std::unique_ptr<reference::ExactGeodesic> reference;
  if (exact) reference = std::make_unique<reference::ExactGeodesic>(testing::exact_geodesic(mesh));
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(mesh.positions.size()) - 1);
  PathStats with, without;
  double with_length = 0, without_length = 0;
  int long_pairs = 0;
  for (int s = 0; s < 3; ++s) {
    const int source = vertex(rng);
    const std::vector<double> d = reference ? reference->distances(source) : std::vector<double>();
    for (int k = 0; k < 10; ++k) {
      const int target = vertex(rng);
      const MeshPoint a = vertex_point(mesh, source), b = vertex_point(mesh, target);
      PathStats one;
      GeodesicPath path, before;
      ASSERT_TRUE(guided.shortest_path(a, b, path, &one, SearchGraph::kDual));
      ASSERT_TRUE(plain.shortest_path(a, b, before, &without, SearchGraph::kDual));
      with += one;
      EXPECT_NEAR((eval_position(mesh, path.start) - eval_position(mesh, a)).norm(), 0, 1e-12);
      EXPECT_NEAR((eval_position(mesh, path.end) - eval_position(mesh, b)).norm(), 0, 1e-12);
      for (size_t j = 1; j < path.strip.size(); ++j) ASSERT_GE(edge_to(mesh, path.strip[j - 1], path.strip[j]), 0);
      const double length = path_length(mesh, path);
      if (reference) EXPECT_GE(length, d[target] * (1 - 1e-9)) << source << " -> " << target;
      if (one.guided == 0) continue;
      ++long_pairs;
      if (reference) EXPECT_LE(length, d[target] * 1.05) << source << " -> " << target;
      with_length += length, without_length += path_length(mesh, before);
    }
  }
  EXPECT_GE(long_pairs, 20);
  EXPECT_EQ(with.guided, long_pairs);
  EXPECT_EQ(without.guided, 0);
  EXPECT_LE(with_length, without_length * (1 + slack)) << with_length << " vs " << without_length;
  EXPECT_LT(with.accepted_flips, without.accepted_flips);
  EXPECT_LT(with.visited_nodes * 4, without.visited_nodes) << with.visited_nodes << " vs " << without.visited_nodes;
}

// The coil's faces are about square: the strip descends towards the guide's path (2026-12-05: 0.76x
// the flips, 0.998x the length).
TEST(CoarseGuide, LongPathsFollowItNeverShorterThanExactAndWithFewerFlips) {
  expect_guided_paths_follow(coil(), testing::thinned_tube(kAlong, kAround, false, 4, 2), false, true, 1e-3);
}

// The knotted tube's are about 9:1: the strip walks the guide's path. (No exact distances here: on
// faces this thin the reference's are not to be trusted, some locally shortest paths come out
// shorter; and where the guide, six vertices round, takes the other way round the tube, the path is
// longer, as in one pair of these: in total a little longer than without.)
TEST(CoarseGuide, OnLongThinFacesTheStripWalksThePath) {
  expect_guided_paths_follow(knot(), testing::thinned_tube(1200, 12, true, 4, 2), true, false, 0.01);
}

// Ends a few faces apart: no guide (the greedy search finds the way at once), the same paths as
// without one.
TEST(CoarseGuide, ShortPathsAreLeftToTheSearch) {
  const TriMesh& mesh = coil();
  GeodesicSolver guided(mesh), plain(mesh);
  set_guide(guided);
  std::mt19937 rng(32);
  PathStats stats;
  for (int k = 0; k < 30; ++k) {
    const MeshPoint a = testing::random_point(mesh, rng);
    MeshPoint b = a;
    for (int step = 0; step < 6; ++step) b.face = std::max(0, mesh.adjacency[b.face][step % 3]);
    GeodesicPath path, before;
    ASSERT_TRUE(guided.shortest_path(a, b, path, &stats, SearchGraph::kDual));
    ASSERT_TRUE(plain.shortest_path(a, b, before, nullptr, SearchGraph::kDual));
    EXPECT_EQ(path.strip, before.strip);
  }
  EXPECT_EQ(stats.guided, 0);
}

// A guide far below the mesh's landmark threshold still gets the mesh's landmarks: its exact search
// would flood the guide without them (the coil's guide here: 3,200 faces).
TEST(CoarseGuide, SmallGuidesGetLandmarks) {
  GeodesicSolver guided(coil());
  set_guide(guided);
  const CoarseGuide* guide = guided.coarse_guide();
  ASSERT_NE(guide, nullptr);
  ASSERT_LT(static_cast<int>(guide->coarse().triangles.size()), ShortestPathOptions{}.landmark_min_faces);
  EXPECT_EQ(guide->landmarks().count(), ShortestPathOptions{}.landmarks);
  EXPECT_GT(guide->bytes(), guide->landmarks().bytes());
}

// The guide's search is exact, so its strip is the guide's shortest from either end: one search per
// path, however long (a guide as fine as the coil, whose paths run to thousands of faces; the
// mesh's own search looks again from the other end from 512).
TEST(CoarseGuide, ItsOwnSearchRunsOncePerPath) {
  GeodesicSolver guided(coil());
  set_guide(guided, testing::thinned_tube(kAlong, kAround, false, 1, 1));
  const CoarseGuide* guide = guided.coarse_guide();
  ASSERT_NE(guide, nullptr);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(coil().positions.size()) - 1);
  int guided_paths = 0, long_guide_paths = 0;
  for (int k = 0; k < 20; ++k) {
    const PathStats before = guide->stats();
    PathStats one;
    GeodesicPath path;
    ASSERT_TRUE(guided.shortest_path(vertex_point(coil(), vertex(rng)), vertex_point(coil(), vertex(rng)), path, &one,
                                     SearchGraph::kDual));
    const int searches = guide->stats().searches - before.searches;
    EXPECT_LE(searches, 1);
    guided_paths += one.guided;
    long_guide_paths += searches == 1 && guide->stats().strip_faces - before.strip_faces >= 512;
  }
  EXPECT_GE(guided_paths, 10);
  EXPECT_GE(long_guide_paths, 3);
}

// The refined search between far ends keeps to the guide's corridor of near-shortest ways: a
// fraction of the nodes the whole mesh's search expands, and paths as accurate against the exact
// distances (a corridor around the guide's one path, or along its edges alone, missed the shortest
// way in some pairs on the benchmarks' meshes). The corridor holds the faces of the whole mesh's
// search's path, and on this small coil (8 turns of 16 quads round) two thirds of the mesh at most.
TEST(CoarseGuide, RefinedSearchKeepsToTheCorridorOfNearShortestWays) {
  const TriMesh& mesh = coil();
  // (The landmark term of the refined search left out of both: the corridor alone against the
  // Euclidean term's flood.)
  ShortestPathOptions options, whole_mesh;
  options.guide_corridor_slack = 0.04;
  options.refined_landmark_share = whole_mesh.refined_landmark_share = 0;
  GeodesicSolver guided(mesh, options), plain(mesh, whole_mesh);
  set_guide(guided);
  reference::ExactGeodesic exact = testing::exact_geodesic(mesh);
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(mesh.positions.size()) - 1);
  PathStats with, without;
  std::vector<int> marks(mesh.triangles.size(), -1), corridor, inside(mesh.triangles.size(), 0);
  CoarseGuide& guide = const_cast<CoarseGuide&>(*guided.coarse_guide());
  int pairs = 0;
  size_t corridor_faces = 0;
  for (int s = 0; s < 2; ++s) {
    const int source = vertex(rng);
    const std::vector<double> d = exact.distances(source);
    for (int k = 0; k < 8; ++k) {
      const int target = vertex(rng);
      const MeshPoint a = vertex_point(mesh, source), b = vertex_point(mesh, target);
      PathStats one, other;
      GeodesicPath path, whole;
      ASSERT_TRUE(guided.shortest_path(a, b, path, &one));
      ASSERT_TRUE(plain.shortest_path(a, b, whole, &other));
      if (one.guided == 0) continue;
      ++pairs, with += one, without += other;
      const double length = path_length(mesh, path);
      EXPECT_GE(length, d[target] * (1 - 1e-9)) << source << " -> " << target;
      EXPECT_LE(length, d[target] * 1.005) << source << " -> " << target;
      ASSERT_TRUE(guide.corridor(a, b, options.guide_corridor_slack, options.guide_corridor_edges, marks, corridor));
      corridor_faces += corridor.size();
      for (int f : corridor) inside[f] = 1;
      int missing = 0;
      for (int f : whole.strip) missing += !inside[f];
      for (int f : corridor) inside[f] = 0;
      EXPECT_LE(missing, static_cast<int>(whole.strip.size()) / 50) << source << " -> " << target;
    }
  }
  EXPECT_GE(pairs, 10);
  EXPECT_LT(corridor_faces, pairs * mesh.triangles.size() * 2 / 3) << corridor_faces / pairs << " faces a pair";
  EXPECT_LT(with.visited_nodes * 4, without.visited_nodes * 3) << with.visited_nodes << " vs " << without.visited_nodes;
  // The marks are left clear for the next user; by default (no slack) the search is the whole mesh's.
  PathStats whole;
  GeodesicSolver by_default(mesh);
  set_guide(by_default);
  GeodesicPath path;
  ASSERT_TRUE(by_default.shortest_path(vertex_point(mesh, 0),
                                       vertex_point(mesh, static_cast<int>(mesh.positions.size()) - 1), path, &whole));
  EXPECT_EQ(whole.guided, 0);
  EXPECT_EQ(std::count(marks.begin(), marks.end(), -1), static_cast<long>(marks.size()));
}

// A bad decimation is refused, naming what is wrong, and the guide set before stays.
TEST(CoarseGuide, RefusesBadTrianglesNamingThemAndKeepsTheEarlierGuide) {
  const TriMesh& mesh = coil();
  GeodesicSolver solver(mesh);
  const size_t before = solver.bytes();
  set_guide(solver);
  const size_t faces = solver.coarse_guide()->coarse().triangles.size();
  EXPECT_EQ(solver.bytes(), before + solver.coarse_guide()->bytes());
  // About 2 bytes per face for the vertex table and the guide's mesh and solver at an eighth of the size.
  EXPECT_LT(solver.coarse_guide()->bytes(), 30 * mesh.triangles.size());
  std::string error;
  const int out_of_range[] = {0, 1, static_cast<int>(mesh.positions.size()) + 5};
  EXPECT_EQ(solver.set_coarse_guide(out_of_range, 1, error), MeshStatus::kInvalidInput);
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
  EXPECT_EQ(solver.set_coarse_guide(out_of_range, 0, error), MeshStatus::kInvalidInput);
  EXPECT_NE(error.find("no faces"), std::string::npos) << error;
  const int negative[] = {0, -1, 2};
  EXPECT_EQ(solver.set_coarse_guide(negative, 1, error), MeshStatus::kInvalidInput);
  EXPECT_NE(error.find("-1"), std::string::npos) << error;
  ASSERT_NE(solver.coarse_guide(), nullptr);
  EXPECT_EQ(solver.coarse_guide()->coarse().triangles.size(), faces);
}

}  // namespace
}  // namespace splinekit::surface
