// Mesh building and locally shortest paths against closed forms.
#include "surface/geodesic.h"
#include "surface/tangent.h"
#include "surface/unfold.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>

namespace splinekit::surface {
namespace {

using testing::Arrays;
using testing::random_point;

// The point of `mesh` at position p (a vertex within 1e-9), as a vertex point.
MeshPoint vertex_at(const TriMesh& mesh, const Vec3& p) {
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if ((mesh.positions[v] - p).norm() < 1e-9) return vertex_point(mesh, static_cast<int>(v));
  ADD_FAILURE() << "no vertex at " << p.transpose();
  return {};
}

TEST(SurfaceMesh, WeldsDropsAndReports) {
  // Two triangles sharing an edge, written with duplicated positions, plus an unused vertex.
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 5, 5, 5};
  const std::vector<int> t = {0, 1, 2, 3, 4, 5};
  TriMesh mesh;
  std::string error;
  ASSERT_EQ(build_mesh(p.data(), 7, t.data(), 2, mesh, error), MeshStatus::kOk);
  EXPECT_EQ(mesh.report.welded_vertices, 2);
  EXPECT_EQ(mesh.report.unreferenced_vertices, 1);
  EXPECT_EQ(mesh.report.used_vertices, 4);
  EXPECT_GE(edge_to(mesh, mesh.mesh_face[0], mesh.mesh_face[1]), 0);  // edge (1, 2) meets the second face
  EXPECT_EQ(mesh.report.boundary_loops, 1);
  EXPECT_EQ(mesh.report.components, 1);
  EXPECT_EQ(mesh.mesh_vertex[3], mesh.mesh_vertex[1]);
  EXPECT_EQ(mesh.mesh_vertex[6], -1);
}

TEST(SurfaceMesh, OrientsFacesAndKeepsFilePoints) {
  // The second face is wound against the first; its points keep their file meaning.
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const std::vector<int> t = {0, 1, 2, 1, 2, 3};
  TriMesh mesh;
  std::string error;
  ASSERT_EQ(build_mesh(p.data(), 4, t.data(), 2, mesh, error), MeshStatus::kOk);
  EXPECT_EQ(mesh.report.flipped_faces, 1);
  const MeshPoint file{1, Vec2(0.2, 0.3)};  // 0.5*p1 + 0.2*p2 + 0.3*p3
  const Vec3 expected = 0.5 * Vec3(1, 0, 0) + 0.2 * Vec3(0, 1, 0) + 0.3 * Vec3(1, 1, 0);
  EXPECT_NEAR((eval_position(mesh, to_mesh_point(mesh, file)) - expected).norm(), 0, 1e-15);
  const MeshPoint back = to_file_point(mesh, to_mesh_point(mesh, file));
  EXPECT_DOUBLE_EQ(back.uv.x(), 0.2);
  EXPECT_DOUBLE_EQ(back.uv.y(), 0.3);
}

TEST(SurfaceMesh, ReportsNonManifoldEdgesAndSplitsBowties) {
  // Three faces on one edge (0, 1), and two fans touching at vertex 5 only.
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 0, 1,  0, 0, -1, 0, 0, 0,  1,
                                 3, 0, 0, 4, 1, 0, 4, -1, 0, 2, 1,  0, 2, -1, 0};
  const std::vector<int> t = {0, 1, 2, 1, 0, 3, 0, 1, 4, 5, 6, 7, 5, 8, 9};
  TriMesh mesh;
  std::string error;
  ASSERT_EQ(build_mesh(p.data(), 10, t.data(), 5, mesh, error), MeshStatus::kOk);
  EXPECT_EQ(mesh.report.non_manifold_edges, 1);
  // Vertex 5, and vertices 0 and 1 whose faces fall apart once the non-manifold edge is cut.
  EXPECT_EQ(mesh.report.non_manifold_vertices, 3);
  // (a flip keeps corner 0)
  const auto &t3 = mesh.triangles[mesh.mesh_face[3]], &t4 = mesh.triangles[mesh.mesh_face[4]];
  EXPECT_NE(t3[0], t4[0]);  // vertex 5 split per fan
  EXPECT_EQ(mesh.file_vertex[t3[0]], 5);
  EXPECT_EQ(mesh.file_vertex[t4[0]], 5);
}

// A double-sided mesh (every face listed again with the other winding, as some exporters write
// them; plus a third copy of one face) is the single-sided mesh: the copies are left out of the
// adjacency and the fans, and points on them are points on the face they repeat.
TEST(SurfaceMesh, ADoubleSidedMeshIsOneSurface) {
  const Arrays once = testing::cube(4);
  Arrays twice = once;
  const int nf = static_cast<int>(once.triangles.size() / 3);
  for (int f = 0; f < nf; ++f)
    for (int k : {0, 2, 1}) twice.triangles.push_back(once.triangles[3 * f + k]);
  for (int k : {1, 2, 0}) twice.triangles.push_back(once.triangles[3 * 7 + k]);  // face 7 a third time, turned
  const TriMesh single = testing::build(once), mesh = testing::build(twice);
  EXPECT_EQ(mesh.report.duplicate_faces, nf + 1);
  EXPECT_EQ(mesh.report.components, 1);
  EXPECT_EQ(mesh.report.non_manifold_edges, 0);
  EXPECT_EQ(mesh.report.non_manifold_vertices, 0);
  EXPECT_EQ(mesh.report.boundary_edges, 0);
  EXPECT_EQ(mesh.positions.size(), single.positions.size());
  // The first copy of each face has its three neighbours; points on the others move to it.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int f = 0; f < static_cast<int>(twice.triangles.size() / 3); ++f) {
    const int first = f < nf ? f : f < 2 * nf ? f - nf : 7;
    for (int k = 0; k < 3; ++k) EXPECT_GE(mesh.adjacency[mesh.mesh_face[first]][k], 0) << "face " << first;
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const MeshPoint on_file{f, Vec2(a, b)};
    const MeshPoint p = to_mesh_point(mesh, on_file);
    EXPECT_EQ(p.face, mesh.mesh_face[first]) << "face " << f;
    // The same point of space as the file's barycentrics on the file face's own corners.
    Vec3 x = Vec3::Zero();
    for (int c = 0; c < 3; ++c) {
      const int v = twice.triangles[3 * f + c];
      x += weights(on_file)[c] * Vec3(twice.positions[3 * v], twice.positions[3 * v + 1], twice.positions[3 * v + 2]);
    }
    EXPECT_LT((eval_position(mesh, p) - x).norm(), 1e-12) << "face " << f;
  }
  // A path between points given on copies is the path between the same points on one side.
  GeodesicSolver solver(mesh), one_side(single);
  GeodesicPath path, reference;
  const MeshPoint a{nf + 3, Vec2(0.2, 0.3)}, b{2 * nf - 5, Vec2(0.4, 0.1)};
  ASSERT_TRUE(solver.shortest_path(to_mesh_point(mesh, a), to_mesh_point(mesh, b), path));
  ASSERT_TRUE(one_side.shortest_path(to_mesh_point(single, {3, Vec2(0.3, 0.2)}),
                                     to_mesh_point(single, {nf - 5, Vec2(0.1, 0.4)}), reference));
  EXPECT_NEAR(path_length(mesh, path), path_length(single, reference), 1e-12);
}

TEST(SurfaceMesh, NumbersNeighboursCloseAndKeepsFileIndices) {
  // A grid whose file lists its faces (and vertices) shuffled, some faces wound the other way.
  const Arrays grid = testing::planar_grid(32);
  const int nv = grid.vertices(), nf = grid.faces();
  std::mt19937 rng(5);
  std::vector<int> vertex_at_file(nv), face_at_file(nf);  // file index -> grid index
  std::iota(vertex_at_file.begin(), vertex_at_file.end(), 0);
  std::iota(face_at_file.begin(), face_at_file.end(), 0);
  std::shuffle(vertex_at_file.begin(), vertex_at_file.end(), rng);
  std::shuffle(face_at_file.begin(), face_at_file.end(), rng);
  std::vector<int> file_of_vertex(nv);
  for (int i = 0; i < nv; ++i) file_of_vertex[vertex_at_file[i]] = i;
  Arrays file;
  for (int i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c) file.positions.push_back(grid.positions[3 * vertex_at_file[i] + c]);
  for (int i = 0; i < nf; ++i) {
    int t[3];
    for (int k = 0; k < 3; ++k) t[k] = file_of_vertex[grid.triangles[3 * face_at_file[i] + k]];
    if (i % 7 == 0) std::swap(t[1], t[2]);
    file.triangles.insert(file.triangles.end(), {t[0], t[1], t[2]});
  }
  const TriMesh mesh = testing::build(file);
  ASSERT_EQ(mesh.report.components, 1);
  // (the winding follows file face 0, one of the reversed ones)
  EXPECT_EQ(mesh.report.flipped_faces, nf - (nf / 7 + 1));

  // File points mean what the file says, both ways.
  for (int f = 0; f < nf; ++f) {
    ASSERT_EQ(mesh.file_face[mesh.mesh_face[f]], f);
    const MeshPoint p{f, Vec2(0.2, 0.7)};
    Vec3 expected = Vec3::Zero();
    const double w[3] = {0.1, 0.2, 0.7};
    for (int k = 0; k < 3; ++k) expected += w[k] * Vec3(file.positions.data() + 3 * file.triangles[3 * f + k]);
    EXPECT_NEAR((eval_position(mesh, to_mesh_point(mesh, p)) - expected).norm(), 0, 1e-15) << "file face " << f;
    const MeshPoint back = to_file_point(mesh, to_mesh_point(mesh, p));
    EXPECT_EQ(back.face, f);
    EXPECT_EQ(back.uv, p.uv);
  }
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_EQ(mesh.positions[v], Vec3(file.positions.data() + 3 * mesh.file_vertex[v]));
    EXPECT_EQ(mesh.mesh_vertex[mesh.file_vertex[v]], static_cast<int>(v));
    EXPECT_GE(corner_of(mesh, mesh.vertex_face[v], static_cast<int>(v)), 0);
  }

  // Neighbours across edges, and the corners of a face, lie close together in mesh order (in the
  // shuffled file order they are a third of the mesh apart on average).
  double face_gap = 0, vertex_gap = 0, file_face_gap = 0;
  int pairs = 0;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.adjacency[f][k];
      if (g < 0) continue;
      face_gap += std::abs(f - g);
      file_face_gap += std::abs(mesh.file_face[f] - mesh.file_face[g]);
      vertex_gap += std::abs(mesh.triangles[f][k] - mesh.triangles[f][(k + 1) % 3]);
      ++pairs;
    }
  EXPECT_GT(file_face_gap / pairs, nf / 4.0);
  EXPECT_LT(face_gap / pairs, nf / 40.0);
  EXPECT_LT(vertex_gap / pairs, nv / 40.0);
}

TEST(SurfaceMesh, RejectsBadInputNamingIt) {
  const std::vector<double> p = {0, 0, 0, 1, 0, 0, 0, std::nan(""), 0};
  const std::vector<int> t = {0, 1, 2};
  TriMesh mesh;
  std::string error;
  EXPECT_EQ(build_mesh(p.data(), 3, t.data(), 1, mesh, error), MeshStatus::kInvalidInput);
  EXPECT_NE(error.find("vertex 2"), std::string::npos);
  const std::vector<double> q = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::vector<int> bad = {0, 1, 3};
  EXPECT_EQ(build_mesh(q.data(), 3, bad.data(), 1, mesh, error), MeshStatus::kInvalidInput);
  EXPECT_NE(error.find("face 0"), std::string::npos);
}

TEST(SearchGraph, NumbersEveryEdgeOnceFromBothSides) {
  // A grid (boundary edges) and a closed mesh: both sides of an edge give its number, every number
  // below graph.edges names one edge, and the edge's half-edge gives the number back.
  for (const TriMesh& mesh : {testing::build(testing::planar_grid(9)), testing::build(testing::cube(3))}) {
    GeodesicSolver solver(mesh);
    const DualGraph& graph = solver.graph();
    int boundary = 0, interior = 0;
    std::vector<int> seen(graph.edges, 0);
    for (int f = 0; f < graph.faces; ++f)
      for (int k = 0; k < 3; ++k) {
        const int e = graph.halfedge_edge[3 * f + k];
        ASSERT_GE(e, 0);
        ASSERT_LT(e, graph.edges);
        ++seen[e];
        const int g = mesh.adjacency[f][k];
        if (g < 0) {
          ++boundary;
        } else {
          ++interior;
          EXPECT_EQ(graph.halfedge_edge[3 * g + edge_to(mesh, g, f)], e);
        }
        const int h = graph.edge_halfedge[e];
        EXPECT_EQ(graph.halfedge_edge[h], e);
      }
    EXPECT_EQ(graph.edges, boundary + interior / 2);
    for (int e = 0; e < graph.edges; ++e)
      EXPECT_EQ(seen[e], mesh.adjacency[graph.edge_halfedge[e] / 3][graph.edge_halfedge[e] % 3] < 0 ? 1 : 2)
          << "edge " << e;
  }
}

TEST(SearchGraph, GivesLongEdgesTheirNodesAndNumbersThemInOrder) {
  // A grid of cells 1/12 wide (jittered) and a long-edge fraction of 1/30 of its diagonal: sides
  // are about 1.8 such lengths, diagonals 2.5, so with one Steiner node per edge the diagonals (and
  // some sides) get more, with four none do; only the long edges are listed. Every edge has
  // `steiner` numbers in edge order, a long edge's unused: its own nodes follow all of those, long
  // edge after long edge; every node is one edge's, and edge_of_node inverts the numbering.
  const TriMesh mesh = testing::build(testing::planar_grid(12, 1, 0.25));
  for (int steiner : {1, 2, 4}) {
    ShortestPathOptions options;
    options.steiner = steiner;
    options.long_edge_fraction = 1.0 / 30;
    GeodesicSolver solver(mesh, options);
    const DualGraph& graph = solver.graph();
    int tail = graph.faces + graph.edges * steiner, long_count = 0;
    std::vector<int> owner(graph.nodes(), -1);
    for (int e = 0; e < graph.edges; ++e) {
      const int h = graph.edge_halfedge[e];
      const auto& t = mesh.triangles[h / 3];
      const double len = (mesh.positions[t[(h % 3 + 1) % 3]] - mesh.positions[t[h % 3]]).norm();
      const int extra = len > graph.long_edge ? static_cast<int>(std::ceil(len / graph.long_edge)) - 1 : 0;
      const int count = std::max(steiner, extra);
      const bool is_long = count > steiner;
      long_count += is_long;
      EXPECT_EQ(graph.is_long(e), is_long) << "edge " << e;
      const auto [first, end] = graph.node_range(e);
      ASSERT_EQ(first, is_long ? tail : graph.faces + e * steiner) << "edge " << e;
      ASSERT_EQ(end - first, count) << "edge " << e;
      for (int n = first; n < end; ++n) {
        ASSERT_EQ(graph.edge_of_node(n), e);
        ASSERT_EQ(owner[n], -1) << "node " << n << " twice";
        owner[n] = e;
      }
      if (is_long) tail += count;
    }
    EXPECT_EQ(graph.nodes(), tail);
    EXPECT_EQ(static_cast<int>(graph.long_edges.size()), long_count);
    EXPECT_TRUE(std::is_sorted(graph.long_edges.begin(), graph.long_edges.end()));
    if (steiner == 4) EXPECT_EQ(long_count, 0);
    if (steiner == 1) EXPECT_GT(long_count, graph.edges / 3);
  }
}

TEST(SearchGraph, ALongEdgeCostsItsNodesNotAnOffsetPerEdge) {
  // The memory of issue 17 (<= ~120 bytes per triangle with the landmarks): a 25,600-triangle coil
  // (landmarks on) with one edge made long by moving a vertex far out, against the same coil as
  // built: the long edge adds a bit per edge, not an offset for every edge.
  testing::Arrays a = testing::coil(800, 16);
  const TriMesh plain = testing::build(a);
  // A vertex on the first ring pulled out along x (its edges get long: beyond 1% of the diagonal;
  // the coil's own edges, up to 1.5%, get no more than the 2 nodes of every edge at that fraction).
  a.positions[0] += 2.0;
  const TriMesh stretched = testing::build(a);
  ShortestPathOptions options;
  options.landmark_min_faces = 0;
  options.long_edge_fraction = 0.01;
  GeodesicSolver p(plain, options), q(stretched, options);
  ASSERT_EQ(p.landmarks().count(), 8);
  EXPECT_TRUE(p.graph().long_edges.empty());
  ASSERT_FALSE(q.graph().long_edges.empty());
  const double faces = static_cast<double>(plain.triangles.size());
  const double per_triangle = (mesh_bytes(plain) + p.bytes()) / faces;
  const double stretched_per_triangle = (mesh_bytes(stretched) + q.bytes()) / faces;
  EXPECT_LE(per_triangle, 120) << per_triangle;
  EXPECT_LE(stretched_per_triangle, 120) << stretched_per_triangle;
  // (one bit per edge, 1.5 edges per triangle: 0.19 bytes; an offset per edge would be 6)
  EXPECT_LT(stretched_per_triangle - per_triangle, 0.25) << per_triangle << " vs " << stretched_per_triangle;
}

TEST(SearchGraph, WeighsTheGreedySearchAboveTheStretchOfLongThinFaces) {
  // A cylinder of 600 x 30 quads (0.0105 around, 0.333 along: 32:1), split in two: around it the
  // dual graph zigzags between centroids a third and two thirds up each quad, per quad width w the
  // hops sqrt((w/3)^2 + (h/3)^2) + sqrt((2w/3)^2 + (h/3)^2) (the worst direction); a jittered grid
  // of near-regular faces stays below 2.
  const int around = 600, up = 30;
  const TriMesh thin = testing::build(testing::cylinder(around, up, 1, 10));
  const double w = 2 * std::sin(kPi / around), h = 10.0 / up;
  const double zigzag = (std::hypot(w / 3, h / 3) + std::hypot(2 * w / 3, h / 3)) / w;
  ShortestPathOptions options;
  options.landmarks = 0;
  const DualSearch search(thin, options);
  EXPECT_GT(search.dual_stretch(), 0.5 * zigzag) << zigzag;
  EXPECT_LT(search.dual_stretch(), 1.05 * zigzag) << zigzag;
  EXPECT_DOUBLE_EQ(search.dual_weight(), 1.25 * search.dual_stretch());
  const TriMesh grid = testing::build(testing::planar_grid(80));
  const DualSearch regular(grid, options);
  EXPECT_GT(regular.dual_stretch(), 1.0);
  EXPECT_LT(regular.dual_stretch(), 2.0);
  EXPECT_DOUBLE_EQ(regular.dual_weight(), options.dual_heuristic_weight);

  // Around a quarter of the cylinder at mid-height: at the stretch's weight the greedy search goes
  // to the target; at weight 3 (below the stretch) it expands the faces within reach.
  const MeshPoint a = vertex_at(thin, Vec3(1, 0, 5)), b = vertex_at(thin, Vec3(0, 1, 5));
  ShortestPathOptions plain = options;
  plain.dual_stretch_weight = 0;
  GeodesicSolver weighed(thin, options), flooded(thin, plain);
  std::vector<int> strip, flooded_strip;
  PathStats stats, flooded_stats;
  ASSERT_TRUE(weighed.initial_strip(a, b, strip, &stats, SearchGraph::kDual));
  ASSERT_TRUE(flooded.initial_strip(a, b, flooded_strip, &flooded_stats, SearchGraph::kDual));
  EXPECT_LT(stats.visited_nodes, 4 * static_cast<int>(strip.size())) << strip.size();
  EXPECT_GT(flooded_stats.visited_nodes, 10 * stats.visited_nodes) << stats.visited_nodes;
  // Both straighten to the quarter circle's chord-polygon length (the geodesic around a cylinder).
  GeodesicPath path, flooded_path;
  weighed.shortest_path(a, b, path, nullptr, SearchGraph::kDual);
  flooded.shortest_path(a, b, flooded_path, nullptr, SearchGraph::kDual);
  const double arc = (around / 4) * w;
  EXPECT_NEAR(path_length(thin, path), arc, 1e-9);
  EXPECT_NEAR(path_length(thin, flooded_path), arc, 1e-9);
}

TEST(ShortestPath, IsTheStraightSegmentOnAPlane) {
  const TriMesh mesh = testing::build(testing::planar_grid(24));
  GeodesicSolver solver(mesh);
  std::mt19937 rng(3);
  std::vector<Vec3> positions;
  for (int trial = 0; trial < 200; ++trial) {
    const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
    GeodesicPath path;
    ASSERT_TRUE(solver.shortest_path(a, b, path));
    const Vec3 pa = eval_position(mesh, a), pb = eval_position(mesh, b);
    EXPECT_NEAR(path_length(mesh, path), (pb - pa).norm(), 1e-9) << "trial " << trial;
    // Every crossing lies on the segment, in order.
    path_positions(mesh, path, positions);
    for (const Vec3& p : positions) EXPECT_NEAR((p - pa).cross(pb - pa).norm(), 0, 1e-9 * (pb - pa).norm() + 1e-12);
    for (size_t i = 0; i + 1 < path.strip.size(); ++i) EXPECT_GE(edge_to(mesh, path.strip[i], path.strip[i + 1]), 0);
  }
}

// A scan in georeferenced coordinates lies millions of units from the origin while it is a few units
// across: the search's single-precision positions are taken relative to the mesh's centre, so the
// paths are those of the same mesh at the origin (before, on spot moved to (5e5, 4e6, 100), float
// positions were 0.25-0.5 apart: strips wandered, and of these 40 pairs paths came out up to 8.5%
// longer and searches 118%).
TEST(ShortestPath, AMeshFarFromTheOriginHasTheSamePaths) {
  const testing::Arrays near = testing::read_mesh(testing::shared_data("meshes/spot.obj"));
  testing::Arrays far = near;
  const double shift[3] = {5e5, 4e6, 100};
  for (size_t i = 0; i < far.positions.size(); ++i) far.positions[i] += shift[i % 3];
  const TriMesh a = testing::build(near), b = testing::build(far);
  ShortestPathOptions options;
  options.landmark_min_faces = 0;  // (spot has 5,856 faces: its landmarks too)
  GeodesicSolver at_origin(a, options), away(b, options);
  ASSERT_EQ(at_origin.landmarks().count(), 8);
  std::mt19937 rng(7);
  double worst_path = 0, worst_search = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const MeshPoint p = random_point(a, rng), q = random_point(a, rng);
    for (SearchGraph graph : {SearchGraph::kRefined, SearchGraph::kDual}) {
      GeodesicPath x, y;
      ASSERT_TRUE(at_origin.shortest_path(p, q, x, nullptr, graph));
      ASSERT_TRUE(away.shortest_path(p, q, y, nullptr, graph));
      // (Up to single-precision rounding: the centres differ in their last bits, and a greedy
      // search's near-ties may go either way.)
      const double length = path_length(a, x);
      worst_path = std::max(worst_path, std::abs(path_length(b, y) - length) / length);
      worst_search =
          std::max(worst_search, std::abs(at_origin.last_search_length() - away.last_search_length()) / length);
    }
  }
  std::printf("  worst relative difference: paths %.2g, searches %.2g\n", worst_path, worst_search);
  EXPECT_LT(worst_path, 1e-5);
  EXPECT_LT(worst_search, 5e-3);
}

// A path straightened through two known paths that meet at a corner c (a mesh vertex half of the
// time, so the strip must go around it) is the straight segment, like the searched one; and on the
// cube the corner between two faces' centres straightens to the unfolded diagonal.
TEST(ShortestPath, StraightensThroughKnownPaths) {
  const TriMesh mesh = testing::build(testing::planar_grid(24));
  GeodesicSolver solver(mesh);
  std::mt19937 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    const MeshPoint a = random_point(mesh, rng), b = random_point(mesh, rng);
    const MeshPoint c =
        trial % 2 ? vertex_point(mesh, static_cast<int>(rng() % mesh.positions.size())) : random_point(mesh, rng);
    std::vector<GeodesicPath> pieces(2);
    ASSERT_TRUE(solver.shortest_path(a, c, pieces[0]));
    ASSERT_TRUE(solver.shortest_path(c, b, pieces[1]));
    GeodesicPath path;
    ASSERT_TRUE(solver.straighten_through(pieces, path)) << "trial " << trial;
    EXPECT_NEAR(path_length(mesh, path), (eval_position(mesh, b) - eval_position(mesh, a)).norm(), 1e-9)
        << "trial " << trial;
    for (size_t i = 0; i + 1 < path.strip.size(); ++i) EXPECT_GE(edge_to(mesh, path.strip[i], path.strip[i + 1]), 0);
  }
  const TriMesh cube = testing::build(testing::cube(4));
  GeodesicSolver on_cube(cube);
  std::vector<GeodesicPath> pieces(2);
  // (0.5, 0.5, 0) -> corner (1, 1, 0) -> (1, 0.5, 0.5): unfolded, the two face centres are 1 apart.
  ASSERT_TRUE(on_cube.shortest_path(vertex_at(cube, {0.5, 0.5, 0}), vertex_at(cube, {1, 1, 0}), pieces[0]));
  ASSERT_TRUE(on_cube.shortest_path(vertex_at(cube, {1, 1, 0}), vertex_at(cube, {1, 0.5, 0.5}), pieces[1]));
  GeodesicPath path;
  ASSERT_TRUE(on_cube.straighten_through(pieces, path));
  EXPECT_NEAR(path_length(cube, path), 1.0, 1e-9);
  // Pieces that do not meet are refused.
  std::swap(pieces[0], pieces[1]);
  EXPECT_FALSE(on_cube.straighten_through(pieces, path));
}

TEST(ShortestPath, StraighteningThroughKnownPathsStopsAtItsPassLimit) {
  // Round a far corner on a grid, semi-stars only (no chords, no zippers): a vertex a pass.
  const TriMesh mesh = testing::build(testing::planar_grid(24, 1, 0));
  ShortestPathOptions options;
  options.chords = options.slides = false;
  GeodesicSolver solver(mesh, options);
  auto at = [&](double x, double y) { return testing::point_at(mesh, Vec3(x, y, 0)); };
  std::vector<GeodesicPath> pieces(2);
  ASSERT_TRUE(solver.shortest_path(at(0.05, 0.5), at(0.5, 0.95), pieces[0]));
  ASSERT_TRUE(solver.shortest_path(at(0.5, 0.95), at(0.95, 0.5), pieces[1]));
  const double straight = 0.9;
  GeodesicPath path;
  PathStats stats;
  ASSERT_TRUE(solver.straighten_through(pieces, path, &stats));
  EXPECT_NEAR(path_length(mesh, path), straight, 1e-9);
  ASSERT_GT(stats.passes, 4);
  // Four passes do not get there: false, and the path so far is still longer.
  PathStats limited;
  EXPECT_FALSE(solver.straighten_through(pieces, path, &limited, 4));
  EXPECT_EQ(limited.passes, 4);
  EXPECT_GT(path_length(mesh, path), straight + 1e-6);
  // Enough passes: true, the same path.
  EXPECT_TRUE(solver.straighten_through(pieces, path, nullptr, stats.passes));
  EXPECT_NEAR(path_length(mesh, path), straight, 1e-9);
}

// A strip that runs just under a row of collinear vertices while both ends lie just above it: the
// funnel path runs along the row, bent where the strip crosses it. Flipping one vertex at a time
// takes one flip per row vertex (19 here); the chain flip moves the strip across the whole
// blocking stretch of the row at once. The result is the straight segment either way.
// Straightens the strip through the shortest paths between consecutive `via` points of a 24 x 24
// grid on the unit square; returns the path's length (flips and frozen vertices in `stats`).
double straighten_via(const std::vector<Vec2>& via, bool chords, PathStats& stats, double chord_min_turn = 0.01,
                      int span_min_bends = ShortestPathOptions().span_min_bends) {
  const TriMesh mesh = testing::build(testing::planar_grid(24, 1, 0));
  ShortestPathOptions options;
  options.chords = chords;
  options.chord_min_turn = chord_min_turn;
  options.span_min_bends = span_min_bends;
  GeodesicSolver solver(mesh, options);
  auto at = [&](const Vec2& p) { return testing::point_at(mesh, Vec3(p.x(), p.y(), 0)); };
  std::vector<GeodesicPath> pieces(via.size() - 1);
  for (size_t i = 0; i + 1 < via.size(); ++i) EXPECT_TRUE(solver.shortest_path(at(via[i]), at(via[i + 1]), pieces[i]));
  GeodesicPath path;
  EXPECT_TRUE(solver.straighten_through(pieces, path, &stats));
  return path_length(mesh, path);
}

TEST(ShortestPath, FlipsAZipperOfCollinearVerticesAtOnce) {
  // The ends just above row 12 of the grid; the strip goes down to just under it, along it, and back
  // up. Semi-star flips alone take the path past one vertex of the row at a time (18 flips).
  const double cell = 1.0 / 24, row = 12 * cell;
  PathStats stats;
  const double length = straighten_via(
      {{0.1, row + 0.3 * cell}, {0.15, row - 0.3 * cell}, {0.85, row - 0.3 * cell}, {0.9, row + 0.3 * cell}}, false,
      stats);
  EXPECT_NEAR(length, 0.8, 1e-9);
  EXPECT_LE(stats.accepted_flips, 5);
  EXPECT_EQ(stats.frozen_vertices, 0);
}

TEST(ShortestPath, CrossesManyRowsAlongAChord) {
  // A strip that dips far below the segment between its ends. Semi-star flips (and zippers) bring
  // the path up one row of vertices at a time; a chord moves it to the line between the
  // neighbouring apices in one go.
  const std::vector<Vec2> via = {{0.1, 0.8}, {0.5, 0.13}, {0.9, 0.8}};
  PathStats with, without;
  EXPECT_NEAR(straighten_via(via, true, with), 0.8, 1e-9);
  EXPECT_NEAR(straighten_via(via, false, without), 0.8, 1e-9);
  EXPECT_LE(with.accepted_flips, 30);
  EXPECT_GE(without.accepted_flips, 60);
  EXPECT_EQ(with.frozen_vertices, 0);
  // Chords are traced only where the path turns by more than chord_min_turn: with a bound above
  // every possible turn (π), and no spans (chords across runs of bends, whatever their turns), the
  // straightening makes exactly the flips it makes without chords.
  PathStats gated;
  EXPECT_NEAR(straighten_via(via, true, gated, 3.2, 0), 0.8, 1e-9);
  EXPECT_EQ(gated.accepted_flips, without.accepted_flips);
}

TEST(UnfoldStrip, LaysFacesIsometricallyAndReusesACommonStartExactly) {
  // Two paths on a cylinder from the same point to nearby targets: their strips start alike.
  const TriMesh mesh = testing::build(testing::cylinder(24, 8));
  GeodesicSolver solver(mesh);
  const MeshPoint a = testing::point_at(mesh, Vec3(std::cos(0.1), std::sin(0.1), 0.3));  // inside a face
  GeodesicPath p1, p2;
  ASSERT_TRUE(solver.shortest_path(a, testing::point_at(mesh, Vec3(-1, 0.05, 1.7)), p1));
  ASSERT_TRUE(solver.shortest_path(a, testing::point_at(mesh, Vec3(-1, -0.05, 1.6)), p2));
  UnfoldedStrip u1, fresh, reused;
  unfold_strip(mesh, p1.strip, u1);
  unfold_strip(mesh, p2.strip, fresh);
  unfold_strip(mesh, p2.strip, reused, &u1);
  size_t common = 0;
  while (common < std::min(p1.strip.size(), p2.strip.size()) && p1.strip[common] == p2.strip[common]) ++common;
  ASSERT_GE(common, 2u);
  ASSERT_LT(common, p2.strip.size());
  ASSERT_EQ(reused.corners.size(), fresh.corners.size());
  for (size_t i = 0; i < fresh.corners.size(); ++i) {
    const auto& t = mesh.triangles[p2.strip[i]];
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(reused.corners[i][k], fresh.corners[i][k]) << "face " << i;
      const double in_space = (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).norm();
      EXPECT_NEAR((fresh.corners[i][(k + 1) % 3] - fresh.corners[i][k]).norm(), in_space, 1e-12) << "face " << i;
    }
  }
  for (size_t i = 0; i < fresh.portals.size(); ++i) {
    EXPECT_EQ(reused.left(i), fresh.left(i));
    EXPECT_EQ(reused.right(i), fresh.right(i));
    EXPECT_EQ(reused.portals[i].left_vertex, fresh.portals[i].left_vertex);
  }
}

TEST(UnfoldStrip, PiecesMovedRigidlyAndJoinedMatchAFreshLayout) {
  // A strip laid out in two pieces, each in its own frame (phase (iii)'s trial strips keep the
  // current layout between changes, moved rigidly), joined into one: the same layout as laying it
  // out in one go, and the vertices shared across the joint at exactly the same points.
  const TriMesh mesh = testing::build(testing::cylinder(24, 8));
  GeodesicSolver solver(mesh);
  GeodesicPath path;
  ASSERT_TRUE(solver.shortest_path(testing::point_at(mesh, Vec3(std::cos(0.1), std::sin(0.1), 0.3)),
                                   testing::point_at(mesh, Vec3(-1, 0.05, 1.7)), path));
  const std::vector<int>& strip = path.strip;
  ASSERT_GE(strip.size(), 8u);
  UnfoldedStrip fresh, tail, u;
  unfold_strip(mesh, strip, fresh);
  const size_t m = strip.size() / 2;
  unfold_strip(mesh, std::vector<int>(strip.begin() + (m - 1), strip.end()), tail);  // from face m-1, its own frame
  ASSERT_GT((tail.corners[0][1] - fresh.corners[m - 1][1]).norm(), 0.1);             // (a different frame indeed)
  append_moved(u, fresh, 0, m, PlaneMotion{});
  append_moved(u, tail, 1, tail.faces.size(), PlaneMotion::between(tail.corners[0], u.corners.back()));
  join(mesh, u, m);
  ASSERT_EQ(u.faces, strip);
  ASSERT_EQ(u.portals.size(), fresh.portals.size());
  for (size_t i = 0; i < strip.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((u.corners[i][k] - fresh.corners[i][k]).norm(), 0, 1e-12) << "face " << i;
  for (size_t i = 0; i < fresh.portals.size(); ++i) {
    EXPECT_EQ(u.portals[i].left_vertex, fresh.portals[i].left_vertex);
    EXPECT_EQ(u.portals[i].right_vertex, fresh.portals[i].right_vertex);
    EXPECT_NEAR((u.left(i) - fresh.left(i)).norm(), 0, 1e-12);
    EXPECT_NEAR((u.right(i) - fresh.right(i)).norm(), 0, 1e-12);
  }
  // Across the joint a shared vertex is one point: in face m-1, in the faces after it around that
  // vertex, and in their portals.
  for (int v : {u.portals[m - 1].left_vertex, u.portals[m - 1].right_vertex}) {
    const Vec2 at = u.corners[m - 1][corner_of(mesh, strip[m - 1], v)];
    for (size_t i = m; i < strip.size() && corner_of(mesh, strip[i], v) >= 0; ++i) {
      EXPECT_EQ(u.corners[i][corner_of(mesh, strip[i], v)], at) << "face " << i;
      const Portal& in = u.portals[i - 1];
      EXPECT_EQ(in.left_vertex == v ? u.left(i - 1) : u.right(i - 1), at) << "portal " << i - 1;
    }
  }
}

TEST(UnfoldStrip, AFaceLaidALittleOffDoesNotScaleTheFacesLaidOnFromIt) {
  // Phase (iii) lays new faces on from the current layout (a chord's walk, a flip's faces), and
  // each pass's layout starts from the last one's: an edge laid 1e-6 too long must not make every
  // face laid on from it 1e-6 too large, or the error reaches the far end of a long strip magnified
  // by its length (on the coil of BENCHMARKS.md it grew ten times a pass). A long strip along a coil:
  // its first face laid a millionth too large, the rest on from it.
  const TriMesh mesh = testing::build(testing::coil(800, 16));
  GeodesicSolver solver(mesh);
  GeodesicPath path;
  ASSERT_TRUE(solver.shortest_path(testing::point_at(mesh, mesh.positions[0]),
                                   testing::point_at(mesh, mesh.positions[mesh.positions.size() - 40]), path));
  const std::vector<int>& strip = path.strip;
  ASSERT_GT(strip.size(), 500u);
  UnfoldedStrip fresh, off;
  unfold_strip(mesh, strip, fresh);
  std::array<Vec2, 3> first = fresh.corners[0];
  for (Vec2& c : first) c = first[0] + (1 + 1e-6) * (c - first[0]);
  append_face(mesh, off, strip[0], first);
  for (size_t i = 1; i < strip.size(); ++i) append_laid(mesh, off, strip[i]);
  double longest = 0, worst_edge = 0;
  for (size_t i = 1; i < strip.size(); ++i) {
    const auto& t = mesh.triangles[strip[i]];
    for (int k = 0; k < 3; ++k) {
      const double in_space = (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).norm();
      longest = std::max(longest, in_space);
      worst_edge = std::max(worst_edge, std::abs((off.corners[i][(k + 1) % 3] - off.corners[i][k]).norm() - in_space));
    }
  }
  // The error stays that of the one edge (about 1e-6 of an edge), however far the strip goes on...
  EXPECT_LT(worst_edge, 2e-6 * longest);
  // ...and the far end lies where a fresh layout puts it, seen from the first face, within a few
  // such errors (scaled, it would be off by a millionth of the strip's length: ~500 edges).
  const size_t n = strip.size() - 1;
  const double reach = (fresh.corners[n][0] - fresh.corners[0][0]).norm();
  ASSERT_GT(reach, 100 * longest);
  EXPECT_LT(std::abs((off.corners[n][0] - off.corners[0][0]).norm() - reach), 10e-6 * longest);
}

TEST(UnfoldStrip, MotionsMoveEachCoordinateByItsFormula) {
  // PlaneMotion moves both coordinates at once (append_moved moves most of a trial strip each pass);
  // lane by lane it must round as (c x - s y + t_x, s x + c y + t_y) does, so that trial strips, and
  // the paths found in them, are the same to the last bit as with the formula written out.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-50, 50), angle(-kPi, kPi);
  UnfoldedStrip src, u;
  for (int i = 0; i < 200; ++i) {
    src.faces.push_back(i);
    src.corners.push_back({Vec2(coord(rng), coord(rng)), Vec2(coord(rng), coord(rng)), Vec2(coord(rng), coord(rng))});
    if (i > 0) src.portals.push_back({});
  }
  for (int trial = 0; trial < 20; ++trial) {
    const double a = angle(rng);
    PlaneMotion m;
    m.c = std::cos(a), m.s = std::sin(a), m.t = Vec2(coord(rng), coord(rng));
    u.faces.clear(), u.corners.clear(), u.portals.clear();
    append_moved(u, src, 0, src.faces.size(), m);
    ASSERT_EQ(u.corners.size(), src.corners.size());
    for (size_t i = 0; i < src.corners.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const Vec2& x = src.corners[i][k];
        const Vec2 by_formula(m.c * x.x() - m.s * x.y() + m.t.x(), m.s * x.x() + m.c * x.y() + m.t.y());
        ASSERT_EQ(m(x), by_formula) << "trial " << trial << " face " << i;
        ASSERT_EQ(u.corners[i][k], by_formula) << "trial " << trial << " face " << i;
      }
  }
}

TEST(UnfoldStrip, LaysPointsOfSpaceInAFacesPlane) {
  // On a plane a strip's layout is a rigid motion of the mesh, so any point of the mesh, however
  // far along the strip, lands where the motion takes it, whichever face of the strip lays it.
  const TriMesh plane = testing::build(testing::planar_grid(12));
  GeodesicSolver solver(plane);
  GeodesicPath path;
  ASSERT_TRUE(solver.shortest_path(testing::point_at(plane, Vec3(0.05, 0.1, 0)),
                                   testing::point_at(plane, Vec3(0.93, 0.88, 0)), path));
  ASSERT_GE(path.strip.size(), 10u);
  UnfoldedStrip u;
  unfold_strip(plane, path.strip, u);
  const PlaneMotion motion = PlaneMotion::between({Vec2(plane.positions[plane.triangles[u.faces[0]][0]].head<2>()),
                                                   Vec2(plane.positions[plane.triangles[u.faces[0]][1]].head<2>()),
                                                   Vec2(plane.positions[plane.triangles[u.faces[0]][2]].head<2>())},
                                                  u.corners[0]);
  for (const Vec3& x : {Vec3(0.05, 0.1, 0), Vec3(0.5, 0.5, 0), Vec3(0.93, 0.88, 0), Vec3(0.2, 0.9, 0)}) {
    for (size_t i : {size_t{0}, u.faces.size() / 2, u.faces.size() - 1}) {
      Vec2 at;
      ASSERT_TRUE(lay_point(plane, u.faces[i], u.corners[i], x, at));
      EXPECT_NEAR((at - motion(Vec2(x.head<2>()))).norm(), 0, 1e-12) << "face " << i;
    }
  }
  // Off the plane: the nearest point of the plane, i.e. the height is dropped.
  Vec2 lifted, dropped;
  ASSERT_TRUE(lay_point(plane, u.faces[3], u.corners[3], Vec3(0.4, 0.6, 0.7), lifted));
  ASSERT_TRUE(lay_point(plane, u.faces[3], u.corners[3], Vec3(0.4, 0.6, 0), dropped));
  EXPECT_NEAR((lifted - dropped).norm(), 0, 1e-12);
}

// Distance from x to a polyline of mesh points.
double polyline_distance(const TriMesh& mesh, const std::vector<MeshPoint>& polyline, const Vec3& x) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k + 1 < polyline.size(); ++k) {
    const Vec3 a = eval_position(mesh, polyline[k]), d = eval_position(mesh, polyline[k + 1]) - a;
    const double t = d.squaredNorm() > 0 ? std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * d - x).norm());
  }
  return best;
}

TEST(ShortestPath, IsTheFunnelPathOfItsOwnStrip) {
  // Phase (iii) lays out its trial strips from the current one and takes up the current funnel path
  // where the strips agree. Whatever it kept, the path it returns must be the one the funnel finds
  // in its final strip laid out afresh (phase (ii) alone on that strip).
  const TriMesh mesh = testing::build(testing::read_mesh(testing::shared_data("meshes/spot.obj")));
  GeodesicSolver solver(mesh);
  ShortestPathOptions funnel_only;
  funnel_only.straighten = false;
  GeodesicSolver plain(mesh, funnel_only);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> face(0, static_cast<int>(mesh.triangles.size()) - 1);
  int flipped = 0;
  for (int i = 0; i < 40; ++i) {
    const MeshPoint a{face(rng), Vec2(0.3, 0.3)}, b{face(rng), Vec2(0.2, 0.5)};
    for (SearchGraph graph : {SearchGraph::kDual, SearchGraph::kRefined}) {
      GeodesicPath path, again;
      PathStats stats;
      ASSERT_TRUE(solver.shortest_path(a, b, path, &stats, graph));
      flipped += stats.accepted_flips;
      std::vector<int> strip = path.strip;
      plain.straighten(path.start, path.end, strip, again);
      ASSERT_EQ(again.strip, path.strip);
      EXPECT_NEAR(path_length(mesh, path), path_length(mesh, again), 1e-12 * mesh.scale) << "pair " << i;
      // The same crossings; where the path runs along an edge of its strip, crossing it at either
      // end is the same polyline, so a crossing that differs must lie on the other path.
      std::vector<MeshPoint> points, other;
      path_points(mesh, again, other);
      for (size_t k = 0; k < path.lerps.size(); ++k) {
        if (std::abs(path.lerps[k] - again.lerps[k]) <= 1e-9) continue;
        path_points(mesh, path, points);
        EXPECT_LT(polyline_distance(mesh, other, eval_position(mesh, points[k + 1])), 1e-9 * mesh.scale)
            << "pair " << i << " crossing " << k;
      }
    }
  }
  EXPECT_GT(flipped, 400);  // (the straightening had work to do)
}

TEST(GeodesicPath, KeepsItsArcLengthsThroughSubPathsAndReversal) {
  // The straightening measures the path's arc lengths in the plane of its strip; sub paths and
  // reversed paths carry them along. They must be the lengths of the polyline in space, and
  // evaluating with them must give the points evaluating without them gives.
  const TriMesh mesh = testing::build(testing::read_mesh(testing::shared_data("meshes/spot.obj")));
  GeodesicSolver solver(mesh);
  GeodesicPath path;
  ASSERT_TRUE(solver.shortest_path(MeshPoint{100, Vec2(0.2, 0.3)}, MeshPoint{15000, Vec2(0.5, 0.1)}, path));
  auto check = [&](const GeodesicPath& p, const char* what) {
    SCOPED_TRACE(what);
    ASSERT_EQ(p.arc.size(), p.lerps.size() + 2);
    std::vector<Vec3> positions;
    path_positions(mesh, p, positions);
    double s = 0;
    for (size_t j = 0; j < positions.size(); ++j) {
      if (j > 0) s += (positions[j] - positions[j - 1]).norm();
      EXPECT_NEAR(p.arc[j], s, 1e-12) << "point " << j;
    }
    GeodesicPath measured = p;
    measured.arc.clear();
    for (double t : {0.1, 0.37, 0.5, 0.83}) {
      const Vec3 x = eval_position(mesh, eval_path(mesh, p, t)), y = eval_position(mesh, eval_path(mesh, measured, t));
      EXPECT_NEAR((x - y).norm(), 0, 1e-12) << "t " << t;
    }
  };
  ASSERT_GE(path.lerps.size(), 10u);
  check(path, "path");
  check(sub_path(mesh, path, 0.2, 0.7), "sub path");
  check(sub_path(mesh, path, 0.31, 0.32), "short sub path");
  check(reversed(mesh, path), "reversed");
  check(reversed(mesh, sub_path(mesh, path, 0.05, 0.9)), "reversed sub path");
}

TEST(ShortestPath, MatchesUnfoldingsOnACube) {
  const TriMesh mesh = testing::build(testing::cube(4));
  GeodesicSolver solver(mesh);
  struct Case {
    Vec3 a, b;
    double length;
  } cases[] = {
      {{0.5, 0.5, 0}, {1, 0.5, 0.5}, 1.0},                 // across one edge
      {{0, 0, 0}, {1, 1, 1}, std::sqrt(5.0)},              // corner to opposite corner
      {{0.5, 0.5, 0}, {0.5, 0.5, 1}, 2.0},                 // opposite face centres
      {{0.25, 0, 0}, {0, 0.75, 1}, std::sqrt(1.0 + 1.0)},  // wraps around the edge x = y = 0... see below
  };
  // The last case: from (0.25, 0, 0) on the bottom edge to (0, 0.75, 1) on the top edge of face x = 0:
  // unfold faces y = 0 and x = 0 into one plane: (0.25, 0) -> (-0.75, 1), length sqrt(1 + 1).
  for (const Case& c : cases) {
    GeodesicPath path;
    ASSERT_TRUE(solver.shortest_path(vertex_at(mesh, c.a), vertex_at(mesh, c.b), path));
    EXPECT_NEAR(path_length(mesh, path), c.length, 1e-9) << c.a.transpose() << " -> " << c.b.transpose();
  }
}

TEST(ShortestPath, EvaluatesAndSplitsByArcLength) {
  const TriMesh mesh = testing::build(testing::planar_grid(16));
  GeodesicSolver solver(mesh);
  const MeshPoint a{3, Vec2(0.2, 0.2)}, b{400, Vec2(0.3, 0.5)};
  GeodesicPath path;
  ASSERT_TRUE(solver.shortest_path(a, b, path));
  const Vec3 pa = eval_position(mesh, a), pb = eval_position(mesh, b);
  for (double t : {0.0, 0.1, 0.37, 0.5, 0.99, 1.0})
    EXPECT_NEAR((eval_position(mesh, eval_path(mesh, path, t)) - (pa + t * (pb - pa))).norm(), 0, 1e-9);
  const GeodesicPath half = sub_path(mesh, path, 0.25, 0.75);
  EXPECT_NEAR(path_length(mesh, half), 0.5 * (pb - pa).norm(), 1e-9);
  const GeodesicPath back = reversed(mesh, path);
  EXPECT_NEAR((eval_position(mesh, eval_path(mesh, back, 0.3)) - (pa + 0.7 * (pb - pa))).norm(), 0, 1e-9);
  const Tangent t0 = start_tangent(mesh, path);
  EXPECT_NEAR((t0.dir - (pb - pa).normalized()).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace splinekit::surface
