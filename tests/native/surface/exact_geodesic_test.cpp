// The exact polyhedral geodesic reference (tests/native/reference/exact_geodesic.h) against closed-form
// distances: planar meshes (Euclidean), a planar L-shape and a square with a hole (paths bending at
// reflex boundary corners), the unit cube and the regular tetrahedron and octahedron (unfoldings),
// and metric invariants on a real mesh (symmetry, triangle inequality, Euclidean lower bound,
// Dijkstra-on-edges upper bound).
#include "../reference/exact_geodesic.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

using splinekit::reference::exact_geodesic_distances;
using splinekit::reference::ExactGeodesic;

struct Mesh {
  std::vector<double> p;  // x y z per vertex
  std::vector<int> t;     // 3 per triangle
  int nv() const { return int(p.size() / 3); }
  int nf() const { return int(t.size() / 3); }
  std::array<double, 3> at(int v) const { return {p[3 * v], p[3 * v + 1], p[3 * v + 2]}; }
};

double dist3(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

std::vector<double> geodesic(const Mesh& m, int source) {
  return exact_geodesic_distances(m.p.data(), m.nv(), m.t.data(), m.nf(), source);
}

// Each triangle of `coarse` split into n*n similar triangles (vertices welded by position), same orientation.
Mesh subdivide(const Mesh& coarse, int n) {
  Mesh m;
  std::map<std::tuple<long long, long long, long long>, int> index;
  auto vertex = [&](const std::array<double, 3>& x) {
    const auto key = std::make_tuple(std::llround(x[0] * 1e9), std::llround(x[1] * 1e9), std::llround(x[2] * 1e9));
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const int id = m.nv();
    m.p.insert(m.p.end(), x.begin(), x.end());
    index.emplace(key, id);
    return id;
  };
  for (int f = 0; f < coarse.nf(); ++f) {
    const auto A = coarse.at(coarse.t[3 * f]), B = coarse.at(coarse.t[3 * f + 1]), C = coarse.at(coarse.t[3 * f + 2]);
    auto id = [&](int i, int j) {  // point A + i/n (B - A) + j/n (C - A)
      std::array<double, 3> x;
      for (int c = 0; c < 3; ++c) x[c] = A[c] + (B[c] - A[c]) * i / n + (C[c] - A[c]) * j / n;
      return vertex(x);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        m.t.insert(m.t.end(), {id(i, j), id(i + 1, j), id(i, j + 1)});
        if (i + j + 1 < n) m.t.insert(m.t.end(), {id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  }
  return m;
}

int find_vertex(const Mesh& m, double x, double y, double z) {
  for (int v = 0; v < m.nv(); ++v)
    if (dist3(m.at(v), {x, y, z}) < 1e-9) return v;
  ADD_FAILURE() << "no vertex at " << x << " " << y << " " << z;
  return -1;
}

// Planar n x n grid over [x0, x0 + w] x [y0, y0 + w] minus cells where `keep_cell` is false, random
// diagonals, interior vertices (not on the domain boundary, not in `fixed`) jittered by up to `jitter`
// cell sizes.
Mesh planar_grid(int n, double w, const std::function<bool(double, double)>& keep_cell, double jitter, unsigned seed,
                 const std::vector<std::array<double, 2>>& fixed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double h = w / n;
  Mesh m;
  std::vector<int> id((n + 1) * (n + 1), -1);
  auto vid = [&](int i, int j) {
    int& v = id[i * (n + 1) + j];
    if (v < 0) {
      v = m.nv();
      m.p.insert(m.p.end(), {i * h, j * h, 0.0});
    }
    return v;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (!keep_cell((i + 0.5) * h, (j + 0.5) * h)) continue;
      const int a = vid(i, j), b = vid(i + 1, j), c = vid(i + 1, j + 1), d = vid(i, j + 1);
      if (rng() & 1)
        m.t.insert(m.t.end(), {a, b, c, a, c, d});
      else
        m.t.insert(m.t.end(), {a, b, d, b, c, d});
    }
  // Boundary vertices: on an edge used by one triangle.
  std::map<std::pair<int, int>, int> count;
  for (int f = 0; f < m.nf(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.t[3 * f + k], b = m.t[3 * f + (k + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<char> boundary(m.nv(), 0);
  for (const auto& [e, c] : count)
    if (c == 1) boundary[e.first] = boundary[e.second] = 1;
  for (int v = 0; v < m.nv(); ++v) {
    bool pinned = boundary[v];
    for (const auto& q : fixed)
      pinned = pinned || (std::abs(m.p[3 * v] - q[0]) < 1e-12 && std::abs(m.p[3 * v + 1] - q[1]) < 1e-12);
    const double dx = u(rng) * jitter * h, dy = u(rng) * jitter * h;
    if (pinned) continue;
    m.p[3 * v] += dx;
    m.p[3 * v + 1] += dy;
  }
  return m;
}

// Is the segment a-b passing through the open box (lo, hi)^2?
bool crosses_open_box(const std::array<double, 2>& a, const std::array<double, 2>& b, double lo, double hi) {
  double t0 = 0, t1 = 1;
  for (int c = 0; c < 2; ++c) {
    const double d = b[c] - a[c];
    if (std::abs(d) < 1e-15) {
      if (a[c] <= lo || a[c] >= hi) return false;
      continue;
    }
    double s0 = (lo - a[c]) / d, s1 = (hi - a[c]) / d;
    if (s0 > s1) std::swap(s0, s1);
    t0 = std::max(t0, s0);
    t1 = std::min(t1, s1);
  }
  if (t1 - t0 < 1e-12) return false;
  const double tm = 0.5 * (t0 + t1);
  for (int c = 0; c < 2; ++c) {
    const double x = a[c] + tm * (b[c] - a[c]);
    if (x <= lo + 1e-12 || x >= hi - 1e-12) return false;
  }
  return true;
}

// Shortest path around a square obstacle (lo, hi)^2 in a convex domain: Dijkstra on the visibility
// graph of {a, b, the four corners} (shortest paths only bend at reflex corners).
double around_square(const std::array<double, 2>& a, const std::array<double, 2>& b, double lo, double hi) {
  std::vector<std::array<double, 2>> pts = {a, b, {lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  const int n = int(pts.size());
  std::vector<double> d(n, INFINITY);
  std::vector<char> done(n, 0);
  d[0] = 0;
  for (int it = 0; it < n; ++it) {
    int u = -1;
    for (int i = 0; i < n; ++i)
      if (!done[i] && (u < 0 || d[i] < d[u])) u = i;
    done[u] = 1;
    for (int i = 0; i < n; ++i)
      if (!done[i] && !crosses_open_box(pts[u], pts[i], lo, hi))
        d[i] = std::min(d[i], d[u] + std::hypot(pts[i][0] - pts[u][0], pts[i][1] - pts[u][1]));
  }
  return d[1];
}

std::vector<double> dijkstra_on_edges(const Mesh& m, int source) {
  std::vector<std::vector<std::pair<int, double>>> adj(m.nv());
  for (int f = 0; f < m.nf(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.t[3 * f + k], b = m.t[3 * f + (k + 1) % 3];
      const double l = dist3(m.at(a), m.at(b));
      adj[a].push_back({b, l});
      adj[b].push_back({a, l});
    }
  std::vector<double> d(m.nv(), INFINITY);
  using QE = std::pair<double, int>;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
  d[source] = 0;
  q.push({0, source});
  while (!q.empty()) {
    auto [du, u] = q.top();
    q.pop();
    if (du > d[u]) continue;
    for (auto [v, l] : adj[u])
      if (du + l < d[v]) q.push({d[v] = du + l, v});
  }
  return d;
}

// Minimal OBJ reader: "v x y z" and "f a b c ..." (a may be a/b/c, negative indices allowed), fans.
Mesh read_obj(const std::string& path) {
  Mesh m;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      double x, y, z;
      s >> x >> y >> z;
      m.p.insert(m.p.end(), {x, y, z});
    } else if (tag == "f") {
      std::vector<int> poly;
      std::string tok;
      while (s >> tok) {
        const int i = std::stoi(tok.substr(0, tok.find('/')));
        poly.push_back(i > 0 ? i - 1 : m.nv() + i);
      }
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) m.t.insert(m.t.end(), {poly[0], poly[k], poly[k + 1]});
    }
  }
  return m;
}

// ../shared/data beside the repository, found from this source file (tests/native/surface/).
std::filesystem::path shared_data() {
  std::filesystem::path file = std::filesystem::absolute(__FILE__);
  return file.parent_path().parent_path().parent_path().parent_path().parent_path() / "shared" / "data";
}

// ---- (1) Planar meshes: geodesic = Euclidean -------------------------------------------------

TEST(ExactGeodesic, JitteredPlanarGridIsEuclidean) {
  const Mesh m = planar_grid(12, 1.0, [](double, double) { return true; }, 0.35, 7, {});
  ASSERT_EQ(m.nf(), 2 * 12 * 12);
  for (int source : {0, m.nv() / 2 + 3, m.nv() - 1}) {
    const auto d = geodesic(m, source);
    for (int v = 0; v < m.nv(); ++v)
      EXPECT_NEAR(d[v], dist3(m.at(source), m.at(v)), 1e-9) << "source " << source << " vertex " << v;
  }
}

TEST(ExactGeodesic, RotatedPlanarGridIsEuclidean) {
  Mesh m = planar_grid(10, 3.0, [](double, double) { return true; }, 0.3, 11, {});
  // Embed in 3-D with a rotation and an offset: only intrinsic lengths may matter.
  const double a = 0.7, b = -1.1;
  for (int v = 0; v < m.nv(); ++v) {
    const double x = m.p[3 * v], y = m.p[3 * v + 1];
    const double x1 = std::cos(a) * x, y1 = y, z1 = std::sin(a) * x;  // about y
    m.p[3 * v] = std::cos(b) * x1 - std::sin(b) * y1 + 5;             // about z
    m.p[3 * v + 1] = std::sin(b) * x1 + std::cos(b) * y1 - 2;
    m.p[3 * v + 2] = z1 + 1;
  }
  const int source = 37;
  const auto d = geodesic(m, source);
  for (int v = 0; v < m.nv(); ++v) EXPECT_NEAR(d[v], dist3(m.at(source), m.at(v)), 1e-9) << "vertex " << v;
}

// ---- (2) Unit cube: unfoldings from the corner (0,0,0) ----------------------------------------

Mesh unit_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.p.insert(m.p.end(), {double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  // Outward-oriented quads split into two triangles each.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) m.t.insert(m.t.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  return m;
}

// From the corner (0,0,0): straight on the three faces through it; on a far face (say x = 1) the
// better of the unfoldings over the edge x=1,z=0 (length sqrt((1+z)^2 + y^2)) and over x=1,y=0
// (sqrt((1+y)^2 + z^2)), i.e. sqrt((1 + min)^2 + max^2) of the two other coordinates.
double cube_corner_distance(double x, double y, double z) {
  const double eps = 1e-12;
  if (x < eps || y < eps || z < eps) return std::sqrt(x * x + y * y + z * z);
  auto far = [](double u, double v) {
    return std::sqrt((1 + std::min(u, v)) * (1 + std::min(u, v)) + std::max(u, v) * std::max(u, v));
  };
  double d = INFINITY;
  if (x > 1 - eps) d = std::min(d, far(y, z));
  if (y > 1 - eps) d = std::min(d, far(x, z));
  if (z > 1 - eps) d = std::min(d, far(x, y));
  return d;
}

TEST(ExactGeodesic, CubeTwelveTriangles) {
  const Mesh m = unit_cube();
  ASSERT_EQ(m.nf(), 12);
  const auto d = geodesic(m, 0);
  EXPECT_NEAR(d[7], std::sqrt(5.0), 1e-12);  // opposite corner
  EXPECT_NEAR(d[1], 1.0, 1e-12);
  EXPECT_NEAR(d[3], std::sqrt(2.0), 1e-12);
  for (int v = 0; v < 8; ++v)
    EXPECT_NEAR(d[v], cube_corner_distance(m.p[3 * v], m.p[3 * v + 1], m.p[3 * v + 2]), 1e-12) << v;
  // Every corner as source: the opposite corner is sqrt(5) away.
  for (int s = 0; s < 8; ++s) EXPECT_NEAR(geodesic(m, s)[7 - s], std::sqrt(5.0), 1e-12) << s;
}

TEST(ExactGeodesic, SubdividedCube) {
  const Mesh m = subdivide(unit_cube(), 4);  // 4 x 4 grid per face
  ASSERT_EQ(m.nv(), 98);
  const int source = find_vertex(m, 0, 0, 0);
  const auto d = geodesic(m, source);
  for (int v = 0; v < m.nv(); ++v)
    EXPECT_NEAR(d[v], cube_corner_distance(m.p[3 * v], m.p[3 * v + 1], m.p[3 * v + 2]), 1e-9) << v;
  EXPECT_NEAR(d[find_vertex(m, 1, 1, 1)], std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(d[find_vertex(m, 1, 0.5, 0.5)], std::sqrt(2.5), 1e-9);  // center of a far face
  EXPECT_NEAR(d[find_vertex(m, 1, 0.5, 1)], std::sqrt(3.25), 1e-9);   // midpoint of a far edge
  EXPECT_NEAR(d[find_vertex(m, 0.5, 0.5, 0)], std::sqrt(0.5), 1e-9);  // center of a near face
  EXPECT_NEAR(d[find_vertex(m, 1, 1, 0.5)], std::sqrt(3.25), 1e-9);   // midpoint of the edge x = y = 1
  // From the center of a face, the center of the opposite face: 1/2 + 1 + 1/2 over a side face.
  const auto dc = geodesic(m, find_vertex(m, 0.5, 0.5, 0));
  EXPECT_NEAR(dc[find_vertex(m, 0.5, 0.5, 1)], 2.0, 1e-9);
  EXPECT_NEAR(dc[find_vertex(m, 1, 1, 1)], std::sqrt(0.25 + 1.5 * 1.5), 1e-9);  // unfold the side face x = 1
}

// ---- (3) Planar domains with reflex boundary corners --------------------------------------------

TEST(ExactGeodesic, LShapeBendsAtTheReflexCorner) {
  // [0,2]^2 minus (1,2)^2: the reflex corner is (1,1).
  auto keep = [](double x, double y) { return !(x > 1 && y > 1); };
  const std::array<double, 2> s = {1.5, 0.5};
  const Mesh m = planar_grid(16, 2.0, keep, 0.3, 3, {s});
  const int source = find_vertex(m, s[0], s[1], 0);
  const auto d = geodesic(m, source);
  int bent = 0;
  for (int v = 0; v < m.nv(); ++v) {
    const std::array<double, 2> p = {m.p[3 * v], m.p[3 * v + 1]};
    double expected = std::hypot(p[0] - s[0], p[1] - s[1]);
    if (crosses_open_box(s, p, 1, 2)) {  // hidden: straight to the corner, then straight on
      expected = std::hypot(1 - s[0], 1 - s[1]) + std::hypot(p[0] - 1, p[1] - 1);
      ++bent;
    }
    EXPECT_NEAR(d[v], expected, 1e-9) << "vertex " << v << " at " << p[0] << "," << p[1];
  }
  EXPECT_GT(bent, 20);
  // A hand case: the far corner (0, 2) of the upper arm is hidden: |s - (1,1)| + |(1,1) - (0,2)|.
  EXPECT_NEAR(d[find_vertex(m, 0, 2, 0)], std::sqrt(0.5) + std::sqrt(2.0), 1e-9);
}

TEST(ExactGeodesic, SquareWithAHole) {
  // [0,3]^2 minus the hole (1,2)^2 (an inner boundary loop).
  auto keep = [](double x, double y) { return !(x > 1 && x < 2 && y > 1 && y < 2); };
  const std::array<double, 2> s = {0.5, 1.5};
  const Mesh m = planar_grid(12, 3.0, keep, 0.3, 5, {s, {2.5, 1.5}});
  const int source = find_vertex(m, s[0], s[1], 0);
  const auto d = geodesic(m, source);
  int bent = 0;
  for (int v = 0; v < m.nv(); ++v) {
    const std::array<double, 2> p = {m.p[3 * v], m.p[3 * v + 1]};
    const double expected = around_square(s, p, 1, 2);
    bent += expected > std::hypot(p[0] - s[0], p[1] - s[1]) + 1e-9;
    EXPECT_NEAR(d[v], expected, 1e-9) << "vertex " << v << " at " << p[0] << "," << p[1];
  }
  EXPECT_GT(bent, 10);
  // Straight across the hole: around it by two corners, 2 * sqrt(1/2) + 1.
  EXPECT_NEAR(d[find_vertex(m, 2.5, 1.5, 0)], 1 + std::sqrt(2.0), 1e-9);
}

// The closed surface of the L-shaped prism ([0,2]^2 minus (1,2)^2) x [0,1], a grid of squares of side h
// on every face, each split in two. The reflex top corner (1,1,1) is a saddle vertex: 270 degrees of
// top face plus two 90-degree walls of the notch.
Mesh l_prism(double h) {
  Mesh m;
  std::map<std::tuple<long long, long long, long long>, int> index;
  auto vertex = [&](double x, double y, double z) {
    const auto key = std::make_tuple(std::llround(x * 1e9), std::llround(y * 1e9), std::llround(z * 1e9));
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    m.p.insert(m.p.end(), {x, y, z});
    return index[key] = m.nv() - 1;
  };
  // Rectangle origin + [0,1] u + [0,1] v with outward normal n.
  auto rect = [&](std::array<double, 3> o, std::array<double, 3> u, std::array<double, 3> v, std::array<double, 3> n) {
    const std::array<double, 3> c = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    if (c[0] * n[0] + c[1] * n[1] + c[2] * n[2] < 0) std::swap(u, v);
    const int nu = int(std::lround(std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) / h));
    const int nv = int(std::lround(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / h));
    auto at = [&](int i, int j) {
      return vertex(o[0] + u[0] * i / nu + v[0] * j / nv, o[1] + u[1] * i / nu + v[1] * j / nv,
                    o[2] + u[2] * i / nu + v[2] * j / nv);
    };
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
        m.t.insert(m.t.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  };
  for (double z : {0.0, 1.0})
    for (const auto& sq : std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {0, 1}})
      rect({sq[0], sq[1], z}, {1, 0, 0}, {0, 1, 0}, {0, 0, z > 0 ? 1.0 : -1.0});
  rect({0, 0, 0}, {0, 2, 0}, {0, 0, 1}, {-1, 0, 0});
  rect({0, 0, 0}, {2, 0, 0}, {0, 0, 1}, {0, -1, 0});
  rect({2, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0});
  rect({0, 2, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0});
  rect({1, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0});  // notch walls
  rect({1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0});
  return m;
}

TEST(ExactGeodesic, PathsBendAtASaddleVertex) {
  const Mesh m = l_prism(0.25);
  const std::array<double, 2> s = {1.75, 0.5};
  const int source = find_vertex(m, s[0], s[1], 1);
  const auto d = geodesic(m, source);
  // On the top face: straight where the notch does not hide the point, else bent at the saddle r.
  // (Over the notch walls the angle at r is at least 180 degrees, so no straight path goes that way.)
  int bent = 0, checked = 0;
  for (int v = 0; v < m.nv(); ++v) {
    if (m.p[3 * v + 2] != 1.0) continue;
    const std::array<double, 2> p = {m.p[3 * v], m.p[3 * v + 1]};
    double expected = std::hypot(p[0] - s[0], p[1] - s[1]);
    if (crosses_open_box(s, p, 1, 2)) {
      expected = std::hypot(1 - s[0], 1 - s[1]) + std::hypot(p[0] - 1, p[1] - 1);
      ++bent;
    }
    ++checked;
    EXPECT_NEAR(d[v], expected, 1e-9) << "vertex " << v << " at " << p[0] << "," << p[1];
  }
  EXPECT_EQ(checked, 65);
  EXPECT_GT(bent, 10);
  EXPECT_NEAR(d[find_vertex(m, 0.5, 1.75, 1)], 2 * std::hypot(0.75, 0.5), 1e-9);
  // Down the outer wall: unfold the wall y = 0 about the top edge, straight from the source.
  EXPECT_NEAR(d[find_vertex(m, 1.0, 0.0, 0.5)], std::hypot(0.75, 0.5 + 0.5), 1e-9);
}

// ---- (4) Regular tetrahedron and octahedron ------------------------------------------------------

TEST(ExactGeodesic, RegularTetrahedron) {
  Mesh coarse;
  const double r = 1 / std::sqrt(8.0);  // edge length 1
  coarse.p = {r, r, r, r, -r, -r, -r, r, -r, -r, -r, r};
  coarse.t = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
  // Coarse: every vertex is one edge away.
  const auto dc = geodesic(coarse, 0);
  for (int v = 1; v < 4; ++v) EXPECT_NEAR(dc[v], 1.0, 1e-12);
  const Mesh m = subdivide(coarse, 3);
  const auto A = coarse.at(0), B = coarse.at(1), C = coarse.at(2), D = coarse.at(3);
  const int source = find_vertex(m, A[0], A[1], A[2]);
  const auto d = geodesic(m, source);
  // Closed form: straight on the faces through A; on BCD the best unfolding over BC, CD or DB. Unfolded
  // over BC, the face BCD becomes BCD' with D' = B + C - A (the two faces form a rhombus).
  auto unfolded = [&](const std::array<double, 3>& P, const std::array<double, 3>& X, const std::array<double, 3>& Y,
                      const std::array<double, 3>& Z) {
    // P = x X + y Y + z Z on face XYZ; unfold over XY: Z -> X + Y - A.
    std::array<double, 3> e1{}, e2{}, w{};
    for (int c = 0; c < 3; ++c) e1[c] = Y[c] - X[c], e2[c] = Z[c] - X[c], w[c] = P[c] - X[c];
    auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    // Barycentric coordinates of P in XYZ.
    const double d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), d20 = dot(w, e1), d21 = dot(w, e2);
    const double den = d00 * d11 - d01 * d01;
    const double y = (d11 * d20 - d01 * d21) / den, z = (d00 * d21 - d01 * d20) / den, x = 1 - y - z;
    std::array<double, 3> Q;
    for (int c = 0; c < 3; ++c) Q[c] = x * X[c] + y * Y[c] + z * (X[c] + Y[c] - A[c]);
    return dist3(A, Q);
  };
  auto on_plane = [](const std::array<double, 3>& P, const std::array<double, 3>& X, const std::array<double, 3>& Y,
                     const std::array<double, 3>& Z) {
    std::array<double, 3> e1, e2, w;
    for (int c = 0; c < 3; ++c) e1[c] = Y[c] - X[c], e2[c] = Z[c] - X[c], w[c] = P[c] - X[c];
    const std::array<double, 3> n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                     e1[0] * e2[1] - e1[1] * e2[0]};
    return std::abs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) < 1e-12;
  };
  for (int v = 0; v < m.nv(); ++v) {
    const auto P = m.at(v);
    double expected;
    if (on_plane(P, A, B, C) || on_plane(P, A, C, D) || on_plane(P, A, D, B))
      expected = dist3(A, P);
    else
      expected = std::min({unfolded(P, B, C, D), unfolded(P, C, D, B), unfolded(P, D, B, C)});
    EXPECT_NEAR(d[v], expected, 1e-9) << v;
  }
  // By hand: the centroid of the opposite face is sqrt(3)/2 + sqrt(3)/6 = 2/sqrt(3) away
  // (height of the near face plus inradius of the far one), more than its 3-D distance sqrt(2/3).
  const int g = find_vertex(m, (B[0] + C[0] + D[0]) / 3, (B[1] + C[1] + D[1]) / 3, (B[2] + C[2] + D[2]) / 3);
  EXPECT_NEAR(d[g], 2 / std::sqrt(3.0), 1e-9);
}

TEST(ExactGeodesic, RegularOctahedron) {
  Mesh coarse;
  coarse.p = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};  // +x -x +y -y N S
  const int N = 4, S = 5;
  coarse.t = {N, 0, 2, N, 2, 1, N, 1, 3, N, 3, 0, S, 2, 0, S, 1, 2, S, 3, 1, S, 0, 3};
  const double e = std::sqrt(2.0), h = e * std::sqrt(3.0) / 2;  // edge, face height
  const auto dc = geodesic(coarse, N);
  EXPECT_NEAR(dc[S], 2 * h, 1e-12);  // sqrt(6): across a rhombus of two faces
  for (int v = 0; v < 4; ++v) EXPECT_NEAR(dc[v], e, 1e-12);
  const Mesh m = subdivide(coarse, 2);
  const auto d = geodesic(m, find_vertex(m, 0, 0, 1));
  EXPECT_NEAR(d[find_vertex(m, 0, 0, -1)], std::sqrt(6.0), 1e-9);
  EXPECT_NEAR(d[find_vertex(m, 0.5, 0, 0.5)], e / 2, 1e-9);  // midpoint of an upper edge
  EXPECT_NEAR(d[find_vertex(m, 0.5, 0.5, 0)], h, 1e-9);      // midpoint of an equator edge
  // Midpoint of a lower edge S-a: in the rhombus N a S b laid flat (a, b at (-+e/2, 0), N, S at
  // (0, +-h)) it sits at (-e/4, -h/2): sqrt(e^2/16 + 9 h^2/4) = sqrt(3.5).
  EXPECT_NEAR(d[find_vertex(m, 0.5, 0, -0.5)], std::sqrt(3.5), 1e-9);
}

// ---- (5) A real mesh: metric invariants ---------------------------------------------------------

TEST(ExactGeodesic, SpotControlMeshIsAMetricBetweenEuclideanAndDijkstra) {
  const auto path = shared_data() / "meshes" / "spot_control_tri.obj";
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " (../shared/data beside the repository)";
  const Mesh m = read_obj(path.string());
  ASSERT_EQ(m.nv(), 188);
  ASSERT_EQ(m.nf(), 372);
  ExactGeodesic solver(m.p.data(), m.nv(), m.t.data(), m.nf());
  const int n = m.nv();
  std::vector<std::vector<double>> D(n);
  for (int s = 0; s < n; ++s) D[s] = solver.distances(s);
  double scale = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      ASSERT_TRUE(std::isfinite(D[a][b]));
      scale = std::max(scale, D[a][b]);
    }
  const double tol = 1e-9 * scale;
  int strictly_shorter = 0;
  for (int a = 0; a < n; ++a) {
    EXPECT_EQ(D[a][a], 0.0);
    const auto dijkstra = dijkstra_on_edges(m, a);
    for (int b = 0; b < n; ++b) {
      EXPECT_NEAR(D[a][b], D[b][a], 1e-9 * std::max(1.0, D[a][b])) << a << " " << b;
      EXPECT_GE(D[a][b], dist3(m.at(a), m.at(b)) - 1e-12 * scale) << a << " " << b;
      EXPECT_LE(D[a][b], dijkstra[b] + 1e-12 * scale) << a << " " << b;
      strictly_shorter += D[a][b] < dijkstra[b] - 1e-6 * scale;
    }
  }
  EXPECT_GT(strictly_shorter, n * n / 2);  // the exact distance is not the edge-graph distance
  int violations = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n; ++c) violations += D[a][c] > D[a][b] + D[b][c] + tol;
  EXPECT_EQ(violations, 0);
}

// ---- Input handling ------------------------------------------------------------------------------

TEST(ExactGeodesic, UnreachableVerticesAreInfinite) {
  Mesh m;
  m.p = {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 0, 6, 5, 0, 5, 6, 0, 9, 9, 9};
  m.t = {0, 1, 2, 3, 4, 5};
  const auto d = geodesic(m, 0);
  EXPECT_NEAR(d[1], 1.0, 1e-15);
  EXPECT_NEAR(d[2], 1.0, 1e-15);
  for (int v : {3, 4, 5, 6}) EXPECT_TRUE(std::isinf(d[v]));
}

TEST(ExactGeodesic, RejectsInconsistentOrientation) {
  const double p[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const int t[] = {0, 1, 2, 1, 2, 3};  // both triangles use the directed edge 1 -> 2
  EXPECT_THROW(exact_geodesic_distances(p, 4, t, 2, 0), std::invalid_argument);
  const int ok[] = {0, 1, 2, 2, 1, 3};
  EXPECT_NO_THROW(exact_geodesic_distances(p, 4, ok, 2, 0));
  EXPECT_THROW(exact_geodesic_distances(p, 4, ok, 2, 4), std::invalid_argument);
}

}  // namespace
