// Bézier curves on meshes (curves.h) against closed forms. On a convex planar domain every manifold
// average A(P, Q; w) is the affine one, so RDC must reproduce Euclidean de Casteljau subdivision and
// OLR Euclidean Boehm knot insertion (adaptive OLR: the Bézier polygons of the leaves of the expansion
// tree), all computed here independently of the core. On curved meshes point insertion must keep the
// interpolation and tangency properties of b/Surf §4.1.3.
#include "surface/curves.h"
#include "common/geometry.h"
#include "surface/tangent.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <tuple>

namespace splinekit::surface {
namespace {

using Poly = std::array<Vec3, 4>;
using testing::point_at;

// ---- Euclidean reference ------------------------------------------------------------------------

Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return (1 - t) * a + t * b; }

// The blossom f(x1, x2, x3) of the cubic Bézier with control points P (de Casteljau with three
// parameters); B(t) = f(t, t, t).
Vec3 blossom(const Poly& P, double x1, double x2, double x3) {
  const double xs[3] = {x1, x2, x3};
  std::array<Vec3, 4> d = P;
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i + 1 < 4 - r; ++i) d[i] = lerp(d[i], d[i + 1], xs[r]);
  return d[0];
}
Vec3 bezier(const Poly& P, double t) { return blossom(P, t, t, t); }

// Open-uniform cubic B-spline control polygon after `levels` rounds of midpoint knot insertion into
// the knot vector 0000 1111 (Boehm's algorithm, one knot at a time).
std::vector<Vec3> boehm(const Poly& P, int levels) {
  constexpr int p = 3;
  std::vector<double> U = {0, 0, 0, 0, 1, 1, 1, 1};
  std::vector<Vec3> ctrl(P.begin(), P.end());
  for (int level = 0; level < levels; ++level) {
    std::vector<double> mids;
    for (size_t k = 0; k + 1 < U.size(); ++k)
      if (U[k + 1] > U[k]) mids.push_back(0.5 * (U[k] + U[k + 1]));
    for (double u : mids) {
      size_t k = 0;  // U[k] <= u < U[k+1]
      while (!(U[k] <= u && u < U[k + 1])) ++k;
      std::vector<Vec3> next;
      for (size_t i = 0; i <= ctrl.size(); ++i) {
        if (i + p <= k) {
          next.push_back(ctrl[i]);
        } else if (i > k) {
          next.push_back(ctrl[i - 1]);
        } else {
          const double a = (u - U[i]) / (U[i + p] - U[i]);
          next.push_back((1 - a) * ctrl[i - 1] + a * ctrl[i]);
        }
      }
      U.insert(U.begin() + k + 1, u);
      ctrl.swap(next);
    }
  }
  return ctrl;
}

// Distance from q to the polyline through `pts`.
double distance_to_polyline(const Vec3& q, const std::vector<Vec3>& pts) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec3 d = pts[i + 1] - pts[i];
    const double l2 = d.squaredNorm();
    const double s = l2 > 0 ? std::clamp((q - pts[i]).dot(d) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, (q - (pts[i] + s * d)).norm());
  }
  return best;
}

// ---- Mesh helpers -------------------------------------------------------------------------------

Vec3 pos(const TriMesh& mesh, const MeshPoint& p) { return eval_position(mesh, p); }

// Angle between two tangents at p (the second expressed on the first one's face).
double tangent_angle(const TriMesh& mesh, const MeshPoint& p, const Tangent& a, const Tangent& b) {
  const Tangent bb = tangent_in_face(mesh, p, b, a.face);
  return std::atan2(a.dir.cross(bb.dir).norm(), a.dir.dot(bb.dir));
}

struct Config {
  Scheme scheme;
  bool adaptive;
  std::string name() const {
    return std::string(scheme == Scheme::kRDC ? "RDC" : "OLR") + (adaptive ? " adaptive" : " uniform");
  }
  TraceOptions options() const {
    TraceOptions o;
    o.scheme = scheme;
    o.adaptive = adaptive;
    return o;
  }
};
const Config kConfigs[] = {{Scheme::kRDC, false}, {Scheme::kRDC, true}, {Scheme::kOLR, false}, {Scheme::kOLR, true}};

// A jittered planar grid over [0, 1]^2 (convex: shortest paths are straight segments) and two
// control polygons in it: an S-shaped one and a looping one whose control polygon crosses itself.
struct Plane {
  TriMesh mesh = testing::build(testing::planar_grid(16));
  std::vector<Poly> polygons = {
      Poly{Vec3(0.1, 0.15, 0), Vec3(0.3, 0.9, 0), Vec3(0.75, 0.05, 0), Vec3(0.9, 0.8, 0)},
      Poly{Vec3(0.2, 0.2, 0), Vec3(0.95, 0.7, 0), Vec3(0.05, 0.85, 0), Vec3(0.7, 0.15, 0)},
  };
  ControlPolygon control(const Poly& P) const {
    return {point_at(mesh, P[0]), point_at(mesh, P[1]), point_at(mesh, P[2]), point_at(mesh, P[3])};
  }
};

TEST(SurfaceCurves, OlrUniformIsBoehmKnotInsertionOnAPlane) {
  Plane plane;
  GeodesicSolver solver(plane.mesh);
  CurveTracer tracer(solver);
  for (const Poly& P : plane.polygons) {
    for (int levels = 1; levels <= 5; ++levels) {
      TraceOptions options;
      options.scheme = Scheme::kOLR;
      options.levels = levels;
      std::vector<MeshPoint> points;
      tracer.subdivide(plane.control(P), options, points);
      const std::vector<Vec3> expected = boehm(P, levels);
      ASSERT_EQ(points.size(), expected.size()) << "levels " << levels;
      ASSERT_EQ(expected.size(), (size_t(1) << levels) + 3);
      for (size_t i = 0; i < points.size(); ++i)
        EXPECT_NEAR((pos(plane.mesh, points[i]) - expected[i]).norm(), 0, 1e-9)
            << "levels " << levels << " point " << i;
    }
  }
}

TEST(SurfaceCurves, RdcUniformIsDeCasteljauSubdivisionOnAPlane) {
  Plane plane;
  GeodesicSolver solver(plane.mesh);
  CurveTracer tracer(solver);
  for (const Poly& P : plane.polygons) {
    for (int levels = 1; levels <= 5; ++levels) {
      TraceOptions options;
      options.scheme = Scheme::kRDC;
      options.levels = levels;
      std::vector<MeshPoint> points;
      tracer.subdivide(plane.control(P), options, points);
      const int leaves = 1 << levels;
      ASSERT_EQ(points.size(), size_t(3 * leaves + 1)) << "levels " << levels;
      for (int k = 0; k < leaves; ++k) {
        // The Bézier sub-polygon of [a, b]: f(a,a,a), f(a,a,b), f(a,b,b), f(b,b,b).
        const double a = double(k) / leaves, b = double(k + 1) / leaves;
        const Vec3 expected[4] = {bezier(P, a), blossom(P, a, a, b), blossom(P, a, b, b), bezier(P, b)};
        for (int i = 0; i < 4; ++i)
          EXPECT_NEAR((pos(plane.mesh, points[3 * k + i]) - expected[i]).norm(), 0, 1e-9)
              << "levels " << levels << " leaf " << k << " point " << i;
      }
    }
  }
}

TEST(SurfaceCurves, EvalIsTheEuclideanBezierOnAPlane) {
  Plane plane;
  GeodesicSolver solver(plane.mesh);
  CurveTracer tracer(solver);
  for (const Poly& P : plane.polygons) {
    const ControlPolygon control = plane.control(P);
    for (const Config& config : kConfigs)
      for (double t : {0.0, 1e-3, 0.013, 0.25, 0.3, 0.5, 0.61803, 0.77, 0.999, 1.0})
        EXPECT_NEAR((pos(plane.mesh, tracer.eval(control, t, config.options())) - bezier(P, t)).norm(), 0, 1e-9)
            << config.name() << " t=" << t;
  }
}

TEST(SurfaceCurves, SplitIsDeCasteljauSubdivisionOnAPlane) {
  Plane plane;
  GeodesicSolver solver(plane.mesh);
  CurveTracer tracer(solver);
  for (const Poly& P : plane.polygons) {
    const ControlPolygon control = plane.control(P);
    for (const Config& config : kConfigs)
      for (double t : {0.1, 1.0 / 3, 0.45, 0.63, 0.9}) {
        ControlPolygon left, right;
        tracer.split(control, t, config.options(), left, right);
        const Vec3 el[4] = {P[0], blossom(P, 0, 0, t), blossom(P, 0, t, t), bezier(P, t)};
        const Vec3 er[4] = {bezier(P, t), blossom(P, t, t, 1), blossom(P, t, 1, 1), P[3]};
        for (int i = 0; i < 4; ++i) {
          EXPECT_NEAR((pos(plane.mesh, left[i]) - el[i]).norm(), 0, 1e-7)
              << config.name() << " t=" << t << " left " << i;
          EXPECT_NEAR((pos(plane.mesh, right[i]) - er[i]).norm(), 0, 1e-7)
              << config.name() << " t=" << t << " right " << i;
        }
      }
  }
}

TEST(SurfaceCurves, TraceFollowsTheEuclideanBezierOnAPlane) {
  Plane plane;
  GeodesicSolver solver(plane.mesh);
  CurveTracer tracer(solver);
  for (const Poly& P : plane.polygons) {
    std::vector<Vec3> curve;
    for (int i = 0; i <= 4096; ++i) curve.push_back(bezier(P, i / 4096.0));
    for (Scheme scheme : {Scheme::kRDC, Scheme::kOLR}) {
      TraceOptions options;  // uniform, default levels
      options.scheme = scheme;
      // The Euclidean subdivided polygon the trace must run along.
      std::vector<Vec3> reference;
      if (scheme == Scheme::kOLR) {
        reference = boehm(P, options.uniform_levels());
      } else {
        const int leaves = 1 << options.uniform_levels();
        for (int k = 0; k < leaves; ++k) {
          const double a = double(k) / leaves, b = double(k + 1) / leaves;
          if (k == 0) reference.push_back(bezier(P, a));
          reference.insert(reference.end(), {blossom(P, a, a, b), blossom(P, a, b, b), bezier(P, b)});
        }
      }
      std::vector<MeshPoint> polyline;
      tracer.trace(plane.control(P), options, polyline);
      ASSERT_GE(polyline.size(), 2u);
      EXPECT_NEAR((pos(plane.mesh, polyline.front()) - P[0]).norm(), 0, 1e-12);
      EXPECT_NEAR((pos(plane.mesh, polyline.back()) - P[3]).norm(), 0, 1e-12);
      double worst_curve = 0, worst_polygon = 0;
      for (const MeshPoint& p : polyline) {
        worst_curve = std::max(worst_curve, distance_to_polyline(pos(plane.mesh, p), curve));
        worst_polygon = std::max(worst_polygon, distance_to_polyline(pos(plane.mesh, p), reference));
      }
      EXPECT_LT(worst_polygon, 1e-9) << (scheme == Scheme::kRDC ? "RDC" : "OLR");
      // The subdivided polygon nears the curve as 4^-levels (size 1: within 1e-3 at 5 levels).
      const double curve_bound = 1e-3 * std::pow(4.0, 5 - options.uniform_levels());
      EXPECT_LT(worst_curve, curve_bound) << (scheme == Scheme::kRDC ? "RDC" : "OLR");
      // Consecutive points share a face: every step stays inside one triangle of the grid.
      for (size_t i = 0; i + 1 < polyline.size(); ++i) {
        bool shared = false;
        for (int f : {polyline[i].face, polyline[i + 1].face}) {
          MeshPoint a, b;
          shared = shared ||
                   (point_in_face(plane.mesh, polyline[i], f, a) && point_in_face(plane.mesh, polyline[i + 1], f, b));
        }
        EXPECT_TRUE(shared) << "points " << i << ", " << i + 1;
      }
    }
  }
}

// Turning angle of the polygon a, b, c at b (radians; 0 straight on, π straight back).
double turn(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - b;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// Adaptive OLR's expansion tree on a plane, computed from Boehm's polygons: node m of level n holds
// points m .. m+3 of boehm(P, n), the B-spline segment over [m, m+1]·2^-n. Below the root a node is a
// leaf when it turns by less than `angle` at both inner points, and at max_levels in any case.
struct EuclideanLeaf {
  int level, interval;
};
struct EuclideanTree {
  std::vector<std::vector<Vec3>> polygons;  // boehm(P, n) for n = 0 .. max_levels
  double angle;
  int max_levels;
  std::vector<EuclideanLeaf> leaves;
  double margin = std::numeric_limits<double>::infinity();  // closest a stop decision came to `angle`

  EuclideanTree(const Poly& P, double angle, int max_levels) : angle(angle), max_levels(max_levels) {
    for (int n = 0; n <= max_levels; ++n) polygons.push_back(boehm(P, n));
    expand(0, 0);
  }
  void expand(int level, int m) {
    if (level < max_levels && level > 0) {
      const std::vector<Vec3>& p = polygons[level];
      const double worst = std::max(turn(p[m], p[m + 1], p[m + 2]), turn(p[m + 1], p[m + 2], p[m + 3]));
      margin = std::min(margin, std::abs(worst - angle));
      if (worst < angle) return leaves.push_back({level, m});
    }
    if (level == max_levels) return leaves.push_back({level, m});
    expand(level + 1, 2 * m);
    expand(level + 1, 2 * m + 1);
  }
};

// Adaptive OLR emits, leaf after leaf, the Bézier polygon of the leaf's interval [a, b] (the curve's
// blossoms f(a,a,a), f(a,a,b), f(a,b,b), f(b,b,b)), each leaf's first point being the previous one's
// last. b/Surf §4.2.1 as written emits the leftmost leaf's B-spline points and then the last B-spline
// point of every further leaf; where the tree's level rises from n to n+1, that point P^{n+1}_{2m+5}
// sits beside the one just emitted, P^n_{m+3} (the same Greville abscissa), and the polygon steps
// back. On a plane the output is checked against the blossoms, and since no leaf is cut by max_levels
// here, every turn of it must stay below the angle bound (within a leaf the Bézier polygon turns less
// than the flat B-spline polygon; at a joint the two handles are collinear). For the same reason the
// core's extra test of the Bézier polygon's flatness never expands a node here, and the tree must be
// the one computed from the B-spline polygons alone.
// A curve cannot cross between parts of a mesh that are not connected: each side the solver cannot
// find is counted (TraceStats::unreachable_paths, which the bindings turn into an error naming the
// curve), in tracing, evaluating and splitting alike; curves on one part count none.
TEST(SurfaceCurves, PathsBetweenSeparatePartsAreCounted) {
  testing::Arrays a = testing::planar_grid(8), b = a;
  const int offset = a.vertices();
  for (size_t i = 0; i < b.positions.size(); i += 3) b.positions[i] += 5;
  for (int& v : b.triangles) v += offset;
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  a.triangles.insert(a.triangles.end(), b.triangles.begin(), b.triangles.end());
  const TriMesh mesh = testing::build(a);
  GeodesicSolver solver(mesh);
  CurveTracer tracer(solver);
  const ControlPolygon one = {point_at(mesh, Vec3(0.1, 0.1, 0)), point_at(mesh, Vec3(0.9, 0.2, 0)),
                              point_at(mesh, Vec3(0.2, 0.8, 0)), point_at(mesh, Vec3(0.9, 0.9, 0))};
  ControlPolygon across = one;
  across[2] = point_at(mesh, Vec3(5.5, 0.5, 0));
  std::vector<MeshPoint> polyline;
  ControlPolygon left, right;
  for (Scheme scheme : {Scheme::kOLR, Scheme::kRDC}) {
    TraceOptions options;
    options.scheme = scheme;
    tracer.stats = {};
    tracer.trace(one, options, polyline);
    tracer.eval(one, 0.3, options);
    tracer.split(one, 0.3, options, left, right);
    EXPECT_EQ(tracer.stats.unreachable_paths, 0);
    EXPECT_GT(tracer.stats.shortest_paths, 0);
    tracer.stats = {};
    tracer.trace(across, options, polyline);
    // P1 -> P2 and P2 -> P3 at least (then every path from a point on one part to one on the other).
    EXPECT_GE(tracer.stats.unreachable_paths, 2);
    for (int k = 0; k < 2; ++k) {
      tracer.stats = {};
      if (k == 0)
        tracer.eval(across, 0.3, options);
      else
        tracer.split(across, 0.3, options, left, right);
      EXPECT_GE(tracer.stats.unreachable_paths, 2) << (k ? "split" : "eval");
    }
  }
}

TEST(SurfaceCurves, OlrAdaptiveEmitsTheLeavesBezierPolygonsOnAPlane) {
  Plane plane;
  GeodesicSolver solver(plane.mesh);
  CurveTracer tracer(solver);
  for (size_t k = 0; k < plane.polygons.size(); ++k) {
    const Poly& P = plane.polygons[k];
    for (double degrees : {5.0, 15.0}) {
      TraceOptions options;
      options.scheme = Scheme::kOLR;
      options.adaptive = true;
      options.angle = degrees * kPi / 180;
      const std::string what = "polygon " + std::to_string(k) + ", " + std::to_string(int(degrees)) + "°";
      const EuclideanTree tree(P, options.angle, options.max_levels);
      // The oracle is not on a knife's edge, the tree changes level, and no leaf is cut.
      ASSERT_GT(tree.margin, 1e-6) << what;
      int lowest = options.max_levels, highest = 0;
      for (const EuclideanLeaf& leaf : tree.leaves) {
        lowest = std::min(lowest, leaf.level);
        highest = std::max(highest, leaf.level);
      }
      ASSERT_LT(lowest, highest) << what;
      ASSERT_LT(highest, options.max_levels) << what;

      std::vector<MeshPoint> points;
      tracer.subdivide(plane.control(P), options, points);
      std::vector<Vec3> expected = {P[0]};
      for (const EuclideanLeaf& leaf : tree.leaves) {
        const double a = std::ldexp(leaf.interval, -leaf.level), b = std::ldexp(leaf.interval + 1, -leaf.level);
        expected.insert(expected.end(), {blossom(P, a, a, b), blossom(P, a, b, b), bezier(P, b)});
      }
      std::vector<Vec3> got;
      for (const MeshPoint& p : points) got.push_back(pos(plane.mesh, p));
      double worst_turn = 0;
      for (size_t i = 1; i + 1 < got.size(); ++i) {
        const double t = turn(got[i - 1], got[i], got[i + 1]);
        EXPECT_LT(t, options.angle) << what << ": point " << i << " of " << got.size() << " turns by " << t * 180 / kPi
                                    << "°";
        worst_turn = std::max(worst_turn, t);
      }
      ASSERT_EQ(got.size(), expected.size())
          << what << ": " << tree.leaves.size() << " leaves, levels " << lowest << ".." << highest;
      for (size_t i = 0; i < got.size(); ++i)
        EXPECT_NEAR((got[i] - expected[i]).norm(), 0, 1e-9) << what << " point " << i;
      std::printf("  [%s] %zu leaves, levels %d..%d, worst turn %.3f°\n", what.c_str(), tree.leaves.size(), lowest,
                  highest, worst_turn * 180 / kPi);
    }
  }
}

// Whether `target` lies on the straightest geodesic from p in direction `dir` (within `tol`), traced
// a little further than `length`.
bool on_straightest(const TriMesh& mesh, const MeshPoint& p, const Tangent& dir, double length, const MeshPoint& target,
                    double tol) {
  StraightestGeodesic g;
  straightest_geodesic(mesh, p, dir, 1.05 * length, g);
  std::vector<Vec3> line;
  for (const MeshPoint& q : g.points) line.push_back(pos(mesh, q));
  return distance_to_polyline(pos(mesh, target), line) < tol;
}

// Point insertion on curved meshes: the two halves interpolate P0, P_t and P3, keep the end
// tangents, and meet with one tangent line at P_t.
//
// What the construction guarantees exactly is checked exactly: P0, P3 kept, P_t = eval(t), the new
// outer handles at fraction t of the tracer's own paths P0→P1 and P2→P3, and the inner handles on
// one straightest geodesic through P_t. What a traced half then uses is the shortest path between
// its control points, which can be a different geodesic: (a) the tracer's path P0→P1 may be only
// locally shortest, and then P0→left[1] is a strictly shorter geodesic leaving P0 elsewhere; (b) the
// inner handles are placed by extending the leaf's de Casteljau arms at P_t ×t/(t−t0) and
// ×(1−t)/(t1−t) along straightest geodesics, and past a vertex of positive curvature a straightest
// geodesic is no longer shortest. Tangent deviations are allowed only with that evidence, and counted.
struct SplitCounts {
  int cases = 0;
  int shorter_arm = 0;  // (a): an end tangent moved, the new arm is shorter than the sub-path
  int longer_path = 0;  // (a): an end tangent moved, the search found a longer geodesic than the sub-path
  int inner_kinks = 0;  // (b): kink > 1e-3 rad at P_t, the handles on one straightest geodesic
  double worst_end = 0, worst_kink = 0;
};

void check_split_on(const TriMesh& mesh, const std::vector<ControlPolygon>& polygons, const char* what,
                    SplitCounts& counts) {
  GeodesicSolver solver(mesh);
  CurveTracer tracer(solver);
  const double tol = 1e-9 * mesh.scale;
  for (size_t n = 0; n < polygons.size(); ++n) {
    const ControlPolygon& control = polygons[n];
    for (const Config& config : kConfigs)
      for (double t : {0.3, 0.45, 0.7}) {
        SCOPED_TRACE(std::string(what) + " polygon " + std::to_string(n) + " " + config.name() +
                     " t=" + std::to_string(t));
        ++counts.cases;
        ControlPolygon left, right;
        tracer.split(control, t, config.options(), left, right);
        EXPECT_NEAR((pos(mesh, left[0]) - pos(mesh, control[0])).norm(), 0, tol);
        EXPECT_NEAR((pos(mesh, right[3]) - pos(mesh, control[3])).norm(), 0, tol);
        EXPECT_NEAR((pos(mesh, left[3]) - pos(mesh, right[0])).norm(), 0, tol);
        const MeshPoint at = tracer.eval(control, t, config.options());
        EXPECT_NEAR((pos(mesh, left[3]) - pos(mesh, at)).norm(), 0, tol);

        // The arms as the tracer sees them: shortest paths on its search graph.
        auto path = [&](const MeshPoint& a, const MeshPoint& b, GeodesicPath& out) {
          return solver.shortest_path(a, b, out, nullptr, config.options().search);
        };
        GeodesicPath p01, p23, p0l, pr3, arm_in, arm_out, back;
        ASSERT_TRUE(path(control[0], control[1], p01));
        ASSERT_TRUE(path(control[2], control[3], p23));
        // The new outer handles: t·|P0P1| along P0→P1 and t·|P2P3| along P2→P3.
        EXPECT_NEAR((pos(mesh, left[1]) - pos(mesh, eval_path(mesh, p01, t))).norm(), 0, tol);
        EXPECT_NEAR((pos(mesh, right[2]) - pos(mesh, eval_path(mesh, p23, t))).norm(), 0, tol);
        // The end tangents of the halves.
        ASSERT_TRUE(path(control[0], left[1], p0l));
        ASSERT_TRUE(path(right[2], control[3], pr3));
        const double at_p0 = tangent_angle(mesh, control[0], start_tangent(mesh, p01), start_tangent(mesh, p0l));
        const double at_p3 = tangent_angle(mesh, control[3], end_tangent(mesh, p23), end_tangent(mesh, pr3));
        // A moved end tangent needs a different geodesic to the new handle: one whose length is not
        // the sub-path's (shorter: the tracer's arm was only locally shortest; longer: the search
        // returned a locally shortest path although the sub-path is a shorter one).
        const double d0 = path_length(mesh, p0l) - t * path_length(mesh, p01);
        const double d3 = path_length(mesh, pr3) - (1 - t) * path_length(mesh, p23);
        for (const auto& [angle, delta, end] :
             {std::tuple<double, double, const char*>{at_p0, d0, "P0"}, {at_p3, d3, "P3"}}) {
          if (angle < 1e-6) {
            EXPECT_NEAR(delta, 0, tol) << end;
            continue;
          }
          EXPECT_GT(std::abs(delta), 1e-12 * mesh.scale)
              << end << " tangent moved by " << angle << " on the same geodesic";
          ++(delta < 0 ? counts.shorter_arm : counts.longer_path);
          counts.worst_end = std::max(counts.worst_end, angle);
        }
        // Tangent continuity at P_t: left[2] → P_t continues straight into P_t → right[1].
        ASSERT_TRUE(path(left[2], left[3], arm_in));
        ASSERT_TRUE(path(right[0], right[1], arm_out));
        ASSERT_TRUE(path(left[3], left[2], back));
        const Tangent in = end_tangent(mesh, arm_in), out = start_tangent(mesh, arm_out),
                      away = start_tangent(mesh, back);
        ASSERT_GT(in.dir.norm(), 0);
        ASSERT_GT(out.dir.norm(), 0);
        const double kink = turning_angle(mesh, left[3], in, out);
        if (kink < 1e-3) continue;
        const bool left_straight =
            on_straightest(mesh, left[3], {out.face, -out.dir}, path_length(mesh, back), left[2], 1e-7 * mesh.scale);
        const bool right_straight = on_straightest(mesh, left[3], {away.face, -away.dir}, path_length(mesh, arm_out),
                                                   right[1], 1e-7 * mesh.scale);
        EXPECT_TRUE(left_straight || right_straight) << "kink " << kink << " rad at P_t not explained";
        ++counts.inner_kinks;
        counts.worst_kink = std::max(counts.worst_kink, kink);
      }
  }
  std::printf(
      "  [%s] split, %d cases: end tangent moved %d times by a shorter and %d by a longer geodesic to the new "
      "handle (worst %.4f rad); kink > 1e-3 rad at P_t %d times, handles on one straightest geodesic (worst "
      "%.4f rad)\n",
      what, counts.cases, counts.shorter_arm, counts.longer_path, counts.worst_end, counts.inner_kinks,
      counts.worst_kink);
}

// Control polygons made of straightest geodesic hops of about `hop` from a random start, so that
// they stay local (handles shorter than the distance at which geodesics stop being shortest).
std::vector<ControlPolygon> hop_polygons(const TriMesh& mesh, int count, double hop, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> face(0, static_cast<int>(mesh.triangles.size()) - 1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ControlPolygon> out;
  while (static_cast<int>(out.size()) < count) {
    double a = 0.2 + 0.6 * u(rng), b = 0.2 * u(rng);
    ControlPolygon poly;
    poly[0] = {face(rng), Vec2(a, b)};
    bool ok = true;
    for (int i = 1; i < 4 && ok; ++i) {
      const double angle = 2 * kPi * u(rng);
      StraightestGeodesic g;
      straightest_geodesic(mesh, poly[i - 1], polar_tangent(mesh, poly[i - 1], angle), hop * (0.6 + 0.8 * u(rng)), g);
      ok = !g.hit_boundary;
      poly[i] = g.end;
    }
    if (ok) out.push_back(poly);
  }
  return out;
}

TEST(SurfaceCurves, SplitKeepsEndsAndTangentsOnACylinder) {
  const TriMesh mesh = testing::build(testing::cylinder(32, 16, 1, 2));
  // Points inside the side, away from the rims; hops well below half the circumference.
  std::vector<ControlPolygon> polygons;
  for (const ControlPolygon& p : hop_polygons(mesh, 40, 0.4, 11)) {
    bool inside = true;
    for (const MeshPoint& q : p) inside = inside && pos(mesh, q).z() > 0.2 && pos(mesh, q).z() < 1.8;
    if (inside && polygons.size() < 4) polygons.push_back(p);
  }
  ASSERT_EQ(polygons.size(), 4u);
  // A developable cylinder has no vertex of positive curvature: straightest geodesics that do not wrap
  // half-way around are the shortest paths, so the arms must be collinear everywhere.
  SplitCounts counts;
  check_split_on(mesh, polygons, "cylinder", counts);
  EXPECT_EQ(counts.shorter_arm + counts.longer_path, 0);
  EXPECT_EQ(counts.inner_kinks, 0);
}

TEST(SurfaceCurves, SplitKeepsEndsAndTangentsOnSpot) {
  const TriMesh mesh = testing::build(testing::read_mesh(testing::shared_data("meshes/spot.obj")));
  SplitCounts counts;
  check_split_on(mesh, hop_polygons(mesh, 10, 0.08 * mesh.scale, 5), "spot", counts);
  // The exceptions are rare: both need a vertex of positive curvature right by a path.
  EXPECT_LE(counts.shorter_arm + counts.longer_path + counts.inner_kinks, counts.cases / 5);
}

}  // namespace
}  // namespace splinekit::surface
