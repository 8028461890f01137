// Catmull-Clark subdivision matrices (wasm/core/skin3d/subdivision.h) against closed forms: the
// cube's first level by hand, the regular torus against its bicubic B-spline surface, boundaries
// against the cubic B-spline curve of the boundary polygon, creases and their decay.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "skin3d/subdivision.h"
#include "test_cages.h"

namespace splinekit::skin3d {
namespace {

using namespace test_cages;
using P3 = std::array<double, 3>;

double dist(const double* a, const P3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Every point of `refined` (3 per point) equals exactly one of `expected` and vice versa.
void expect_same_set(const std::vector<double>& refined, const std::vector<P3>& expected, double tol) {
  ASSERT_EQ(refined.size(), 3 * expected.size());
  std::vector<int> used(expected.size(), 0);
  for (size_t r = 0; r < expected.size(); ++r) {
    int match = -1;
    for (size_t k = 0; k < expected.size(); ++k)
      if (dist(&refined[3 * r], expected[k]) <= tol) match = int(k);
    ASSERT_GE(match, 0) << "refined vertex " << r << " (" << refined[3 * r] << ", " << refined[3 * r + 1] << ", "
                        << refined[3 * r + 2] << ") is not an expected point";
    ++used[match];
  }
  for (size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(used[k], 1) << "expected point " << k;
}

TEST(Subdivision, CubeLevelOneByHand) {
  // Cube [-1,1]³. Face points: the face centres (±1 on one axis). Edge points: (v0 + v1 + F_a + F_b)/4
  // = ±3/4 on the edge's two fixed axes, 0 on the third. Vertex points (valence 3):
  // ((n−2)v + mean(neighbours) + mean(face points))/n = (v + v/3 + v/3)/3 = 5/9 v.
  std::vector<P3> expected;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) expected.push_back({5.0 / 9 * sx, 5.0 / 9 * sy, 5.0 / 9 * sz});
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 : {-1, 1})
      for (int s2 : {-1, 1}) {
        P3 p{0, 0, 0};
        p[(axis + 1) % 3] = 0.75 * s1, p[(axis + 2) % 3] = 0.75 * s2;
        expected.push_back(p);
      }
  for (int axis = 0; axis < 3; ++axis)
    for (int s : {-1, 1}) {
      P3 p{0, 0, 0};
      p[axis] = s;
      expected.push_back(p);
    }
  const std::vector<double> refined = refine(read_cage("cube_quad.obj"), 1);
  expect_same_set(refined, expected, 1e-12);
  // Vertex points come first, in cage order.
  const Cage cube = read_cage("cube_quad.obj");
  for (int v = 0; v < 8; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(refined[3 * v + a], 5.0 / 9 * cube.V[3 * v + a], 1e-15);
}

// Uniform cubic B-spline basis centred at 0 (support [−2, 2]).
double bspline(double t) {
  t = std::abs(t);
  if (t < 1) return (4 - 6 * t * t + 3 * t * t * t) / 6;
  if (t < 2) return (2 - t) * (2 - t) * (2 - t) / 6;
  return 0;
}

TEST(Subdivision, RegularTorusIsItsBicubicBSplineSurface) {
  // torus_quad.obj: 12 × 6 grid, vertex 6i + j, periodic in both directions, every vertex of
  // valence 4. Its limit surface is S(u, v) = Σ_ab B(u − a) B(v − b) P_ab. Independently of the
  // subdivision code, refine the periodic grid by the 1D cubic B-spline rules (even: (1, 6, 1)/8,
  // odd: (1, 1)/2) along each direction; check that this grid G_k is the B-spline's control net at
  // spacing 2^−k (its limit points (1,4,1)⊗(1,4,1)/36 equal S at the nodes), that M · cage is G_k as
  // a point set, and that G_k approaches S(nodes) as k grows.
  const Cage torus = read_cage("torus_quad.obj");
  const int n0 = 12, m0 = 6;
  ASSERT_EQ(torus.nv(), n0 * m0);
  auto surface = [&](double u, double v) {
    P3 s{0, 0, 0};
    for (int a = int(std::floor(u)) - 2; a <= int(std::floor(u)) + 2; ++a)
      for (int b = int(std::floor(v)) - 2; b <= int(std::floor(v)) + 2; ++b) {
        const double w = bspline(u - a) * bspline(v - b);
        const int i = ((a % n0) + n0) % n0, j = ((b % m0) + m0) % m0;
        for (int d = 0; d < 3; ++d) s[d] += w * torus.V[3 * (m0 * i + j) + d];
      }
    return s;
  };
  std::vector<P3> grid(size_t(n0) * m0);
  for (int i = 0; i < n0; ++i)
    for (int j = 0; j < m0; ++j)
      grid[m0 * i + j] = {torus.V[3 * (m0 * i + j)], torus.V[3 * (m0 * i + j) + 1], torus.V[3 * (m0 * i + j) + 2]};
  int n = n0, m = m0;
  double previous_gap = INFINITY;
  for (int k = 1; k <= 3; ++k) {
    // Refine along i, then along j.
    std::vector<P3> gi(size_t(2 * n) * m), gij(size_t(2 * n) * 2 * m);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j)
        for (int d = 0; d < 3; ++d) {
          const double a = grid[m * ((i + n - 1) % n) + j][d], b = grid[m * i + j][d],
                       c = grid[m * ((i + 1) % n) + j][d];
          gi[m * (2 * i) + j][d] = (a + 6 * b + c) / 8;
          gi[m * (2 * i + 1) + j][d] = (b + c) / 2;
        }
    n *= 2;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j)
        for (int d = 0; d < 3; ++d) {
          const double a = gi[m * i + (j + m - 1) % m][d], b = gi[m * i + j][d], c = gi[m * i + (j + 1) % m][d];
          gij[2 * m * i + 2 * j][d] = (a + 6 * b + c) / 8;
          gij[2 * m * i + 2 * j + 1][d] = (b + c) / 2;
        }
    m *= 2;
    grid = gij;
    const double h = 1.0 / (1 << k);
    double gap = 0, limit_error = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) {
        const P3 s = surface(i * h, j * h);
        P3 lim{0, 0, 0};
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj) {
            const double w = (di == 0 ? 4.0 : 1.0) * (dj == 0 ? 4.0 : 1.0) / 36;
            for (int d = 0; d < 3; ++d) lim[d] += w * grid[m * ((i + di + n) % n) + (j + dj + m) % m][d];
          }
        limit_error = std::max(limit_error, dist(lim.data(), s));
        gap = std::max(gap, dist(grid[m * i + j].data(), s));
      }
    EXPECT_LT(limit_error, 1e-12) << "level " << k;
    // The limit stencils on the level-k mesh put M · cage onto S exactly.
    Subdivision sub;
    sub.build(torus.mesh(), k, true);
    RowSparse L;
    limit_stencils(sub.refined_mesh(), L);
    std::vector<double> fine(3 * size_t(sub.refined_vertex_count())), limit(fine.size());
    sub.apply(torus.V.data(), 3, fine.data());
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(limit.data(), L.rows(), 3) =
        L * Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(fine.data(), L.cols(), 3);
    std::vector<P3> nodes;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) nodes.push_back(surface(i * h, j * h));
    expect_same_set(limit, nodes, 1e-12);
    EXPECT_LT(gap, previous_gap / 3) << "level " << k << ": the control net approaches the surface ~4× per level";
    previous_gap = gap;
    expect_same_set(refine(torus, k), grid, 1e-12);
  }
}

TEST(Subdivision, RowsAreAffineOnEveryCage) {
  // Every refined vertex is an affine combination of cage vertices with non-negative weights.
  for (const char* name : kSharedCages) {
    Subdivision s;
    s.build(read_cage(name).mesh(), 2);
    const RowSparse M = s.compose();
    for (int r = 0; r < M.rows(); ++r) {
      double sum = 0, lowest = 0;
      for (RowSparse::InnerIterator it(M, r); it; ++it) sum += it.value(), lowest = std::min(lowest, it.value());
      ASSERT_NEAR(sum, 1.0, 1e-12) << name << " row " << r;
      ASSERT_GE(lowest, 0.0) << name << " row " << r;
    }
  }
}

TEST(Subdivision, OpenSheetHasCubicBSplineBoundaryAndKeepsCorners) {
  // A flat 3 × 2 sheet: its boundary y = 0 refines as the cubic B-spline curve of the boundary
  // polygon with its end points kept (end: x; interior even: (1, 6, 1)/8; odd: midpoint).
  const Cage c = sheet(3, 2);
  for (int k = 1; k <= 3; ++k) {
    std::vector<double> xs = {0, 1, 2, 3};
    for (int l = 0; l < k; ++l) {
      std::vector<double> next;
      for (size_t i = 0; i < xs.size(); ++i) {
        const bool end = i == 0 || i + 1 == xs.size();
        next.push_back(end ? xs[i] : (xs[i - 1] + 6 * xs[i] + xs[i + 1]) / 8);
        if (i + 1 < xs.size()) next.push_back((xs[i] + xs[i + 1]) / 2);
      }
      xs = next;
    }
    const std::vector<double> r = refine(c, k);
    std::vector<double> on_boundary;
    for (size_t v = 0; v < r.size() / 3; ++v) {
      EXPECT_EQ(r[3 * v + 2], 0.0);
      if (r[3 * v + 1] == 0.0) on_boundary.push_back(r[3 * v]);
    }
    std::sort(on_boundary.begin(), on_boundary.end());
    ASSERT_EQ(on_boundary.size(), xs.size()) << "level " << k;
    for (size_t i = 0; i < xs.size(); ++i) EXPECT_NEAR(on_boundary[i], xs[i], 1e-14) << "level " << k;
    // Corners stay (vertex points come first, in cage order).
    for (int corner : {0, 3, 8, 11})
      for (int a = 0; a < 3; ++a) EXPECT_EQ(r[3 * corner + a], c.V[3 * corner + a]);
  }
}

Cage cube_with_sharp_edges(double sharpness) {
  Cage c = read_cage("cube_quad.obj");
  const PolyMesh m = c.mesh();
  for (int e = 0; e < m.edge_count(); ++e)
    c.creases.push_back({m.edge_vertices[2 * e], m.edge_vertices[2 * e + 1], sharpness});
  return c;
}

TEST(Subdivision, InfinitelySharpCubeStaysACube) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> sharp = refine(cube_with_sharp_edges(inf), 3),
                            smooth = refine(read_cage("cube_quad.obj"), 3);
  for (size_t v = 0; v < sharp.size() / 3; ++v) {
    const double norm = std::max({std::abs(sharp[3 * v]), std::abs(sharp[3 * v + 1]), std::abs(sharp[3 * v + 2])});
    EXPECT_NEAR(norm, 1.0, 1e-14) << "vertex " << v << " left the cube's surface";
    const double inside = std::max({std::abs(smooth[3 * v]), std::abs(smooth[3 * v + 1]), std::abs(smooth[3 * v + 2])});
    EXPECT_LT(inside, 1.0) << "the smooth cube's vertex " << v << " should lie strictly inside";
  }
  const Cage cube = read_cage("cube_quad.obj");
  for (int v = 0; v < 8; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(sharp[3 * v + a], cube.V[3 * v + a]) << "corner " << v;
  // Its limit surface is the cube too: limit points on the faces, corners kept, edges straight.
  Subdivision sub;
  sub.build(cube_with_sharp_edges(inf).mesh(), 2, true);
  RowSparse L;
  limit_stencils(sub.refined_mesh(), L);
  const std::vector<double> fine = refine(cube_with_sharp_edges(inf), 2);
  for (int r = 0; r < L.rows(); ++r) {
    double p[3] = {0, 0, 0};
    for (RowSparse::InnerIterator it(L, r); it; ++it)
      for (int a = 0; a < 3; ++a) p[a] += it.value() * fine[3 * it.col() + a];
    EXPECT_NEAR(std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}), 1.0, 1e-14) << "limit of vertex " << r;
    if (r < 8)
      for (int a = 0; a < 3; ++a) EXPECT_EQ(p[a], cube.V[3 * r + a]);
  }
}

TEST(Subdivision, SemiSharpCreasesDecayByOnePerLevel) {
  // Sharpness 2 acts as infinitely sharp for two levels, then the creases are smooth: the matrices
  // agree with the infinitely sharp ones at levels 1 and 2, and differ at level 3.
  const double inf = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= 3; ++k) {
    const std::vector<double> semi = refine(cube_with_sharp_edges(2.0), k),
                              sharp = refine(cube_with_sharp_edges(inf), k);
    double diff = 0;
    for (size_t i = 0; i < semi.size(); ++i) diff = std::max(diff, std::abs(semi[i] - sharp[i]));
    if (k <= 2)
      EXPECT_LT(diff, 1e-15) << "level " << k;
    else
      EXPECT_GT(diff, 1e-3) << "level " << k;
  }
  // Sharpness ½ on one edge at level 1: its edge point halfway between the smooth and sharp rules.
  Cage half = read_cage("cube_quad.obj"), full = half;
  half.creases.push_back({0, 1, 0.5});
  full.creases.push_back({0, 1, inf});
  const PolyMesh m = half.mesh();
  const int e = find_edge(m, 0, 1), row = m.vertex_count + e;
  const std::vector<double> rh = refine(half, 1), rf = refine(full, 1), rs = refine(read_cage("cube_quad.obj"), 1);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(rh[3 * row + a], 0.5 * (rf[3 * row + a] + rs[3 * row + a]), 1e-15);
}

TEST(Subdivision, CornerTagsKeepTheVertexForTheirSharpness) {
  const double inf = std::numeric_limits<double>::infinity();
  const Cage cube = read_cage("cube_quad.obj");
  auto with_corner = [&](double s) {
    Cage c = cube;
    c.corners.push_back({0, s});
    return c;
  };
  const P3 v0 = {cube.V[0], cube.V[1], cube.V[2]};
  // Infinitely sharp: vertex 0's descendant stays on it at every level, and so does its limit.
  for (int k = 1; k <= 3; ++k) EXPECT_EQ(dist(refine(with_corner(inf), k).data(), v0), 0.0) << "level " << k;
  Subdivision limit;
  limit.build(with_corner(inf).mesh(), 2, true);
  std::vector<double> fine(3 * size_t(limit.refined_vertex_count()));
  limit.apply(cube.V.data(), 3, fine.data());
  RowSparse L;
  limit_stencils(limit.refined_mesh(), L);
  Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> F(fine.data(),
                                                                                limit.refined_vertex_count(), 3);
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> lim = L * F;
  EXPECT_EQ(dist(lim.data(), v0), 0.0);
  // Sharpness 2: a corner for two levels (exactly v), smooth from the third (it moves inward).
  EXPECT_EQ(dist(refine(with_corner(2.0), 2).data(), v0), 0.0);
  EXPECT_GT(dist(refine(with_corner(2.0), 3).data(), v0), 1e-3);
  // Sharpness ½: level 1's vertex point halfway between v and the smooth one; nothing else moves.
  const std::vector<double> half = refine(with_corner(0.5), 1), smooth = refine(cube, 1);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(half[a], 0.5 * (v0[a] + smooth[a]), 1e-15);
  for (size_t i = 3; i < half.size(); ++i) EXPECT_EQ(half[i], smooth[i]) << "coordinate " << i;
  // The tag decays on vertex 0's descendants: 2 → 1 → 0.
  Subdivision two;
  two.build(with_corner(2.0).mesh(), 1, true);
  EXPECT_EQ(two.refined_mesh().vertex_sharpness[0], 1.0);
  for (size_t v = 1; v < two.refined_mesh().vertex_sharpness.size(); ++v)
    EXPECT_EQ(two.refined_mesh().vertex_sharpness[v], 0.0);
  // Bad tags.
  PolyMesh m = cube.mesh();
  const Corner outside{8, 1.0}, zero{0, 0.0};
  EXPECT_NE(apply_corners(&outside, 1, m).find("outside 0..7"), std::string::npos);
  EXPECT_NE(apply_corners(&zero, 1, m).find("positive"), std::string::npos);
}

TEST(Subdivision, CarKeepsItsSharpEdges) {
  // The car's crease tags (sharpness ≥ 3 after 3 levels... or infinitely sharp) keep the vertex
  // points of crease vertices on the crease: a crease vertex with two sharp edges follows the
  // curve rule (6v + a + b)/8 at level 1.
  const Cage car = read_cage("catmark_car.obj");
  ASSERT_EQ(car.creases.size(), 314u);
  const PolyMesh m = car.mesh();
  Subdivision s;
  s.build(m, 1);
  int checked = 0;
  for (int v = 0; v < m.vertex_count; ++v) {
    std::vector<int> ends;
    bool boundary = false;
    for (int q = m.vertex_edge_start[v]; q < m.vertex_edge_start[v + 1]; ++q) {
      const int e = m.vertex_edges[q];
      boundary |= m.boundary_edge(e);
      if (m.edge_sharpness[e] >= 1) ends.push_back(m.other_end(e, v));
    }
    if (ends.size() != 2 || boundary) continue;
    bool ok = true;
    for (RowSparse::InnerIterator it(s.step(0), v); it; ++it) {
      const double want = it.col() == v ? 0.75 : (it.col() == ends[0] || it.col() == ends[1]) ? 0.125 : 0.0;
      ok &= std::abs(it.value() - want) < 1e-15;
    }
    EXPECT_TRUE(ok) << "crease vertex " << v;
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(Subdivision, RejectsBadCages) {
  PolyMesh m;
  const int tri_sizes[3] = {3, 3, 3};
  const int nonmanifold[9] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  EXPECT_NE(make_poly_mesh(5, tri_sizes, 3, nonmanifold, m).find("non-manifold edge 1-2"), std::string::npos);
  const int quad_size[1] = {4};
  const int repeated[4] = {0, 1, 2, 1};
  EXPECT_NE(make_poly_mesh(3, quad_size, 1, repeated, m).find("face 1 repeats vertex 2"), std::string::npos);
  const int out_of_range[3] = {0, 1, 7};
  EXPECT_NE(make_poly_mesh(3, tri_sizes, 1, out_of_range, m).find("outside"), std::string::npos);
  EXPECT_NE(make_poly_mesh(3, tri_sizes, 0, out_of_range, m).find("no faces"), std::string::npos);
  const int ok[3] = {0, 1, 2};
  ASSERT_EQ(make_poly_mesh(3, tri_sizes, 1, ok, m), "");
  const Crease not_an_edge{0, 5, 1.0}, negative{0, 1, -1.0};
  EXPECT_NE(apply_creases(&not_an_edge, 1, m).find("not joined by an edge"), std::string::npos);
  EXPECT_NE(apply_creases(&negative, 1, m).find("positive"), std::string::npos);
}

}  // namespace
}  // namespace splinekit::skin3d
