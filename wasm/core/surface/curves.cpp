#include "surface/curves.h"

#include "surface/tangent.h"

#include <algorithm>
#include <cmath>

namespace splinekit::surface {

namespace {

bool same_point(const TriMesh& mesh, const MeshPoint& a, const MeshPoint& b) {
  return (eval_position(mesh, a) - eval_position(mesh, b)).norm() <= 1e-12 * mesh.scale;
}

// OLR stencils: point i of level n+1 from the N points of level n (global indices). `avg(j, w)` is
// A(P_j, P_{j+1}; w); `mix(x, y)` is A(x, y; 1/2).
template <class Pt, class Avg, class Mix>
MeshPoint olr_point(int level, int N, int i, Pt pt, Avg avg, Mix mix) {
  const int M = 2 * N - 3;
  if (level == 0) {  // Bézier halves as a B-spline: P0, midpoints, P3
    if (i == 0) return pt(0);
    if (i == 4) return pt(3);
    return avg(i - 1, 0.5);
  }
  if (level == 1) {  // knots 0000 ½ 1111 -> 0000 ¼ ½ ¾ 1111 (Boehm): 3/16 10/16 3/16 in the middle
    switch (i) {
      case 0: return pt(0);
      case 1: return avg(0, 0.5);
      case 2: return avg(1, 0.25);
      case 3: return mix(avg(1, 0.625), avg(2, 0.375));
      case 4: return avg(2, 0.75);
      case 5: return avg(3, 0.5);
      default: return pt(4);
    }
  }
  // Eq. 10 at the ends (and its mirror image), eq. 9 in the middle.
  if (i == 0) return pt(0);
  if (i == 1) return avg(0, 0.5);
  if (i == 2) return avg(1, 0.25);
  if (i == 3) return mix(avg(1, 0.625), avg(2, 0.25));
  if (i == M - 1) return pt(N - 1);
  if (i == M - 2) return avg(N - 2, 0.5);
  if (i == M - 3) return avg(N - 3, 0.75);
  if (i == M - 4) return mix(avg(N - 3, 0.375), avg(N - 4, 0.75));
  if (i % 2 == 0) return avg(i / 2, 0.5);
  const int j = (i - 1) / 2;
  return mix(avg(j, 0.75), avg(j + 1, 0.25));
}

// Knot u_k of the open-uniform knot vector of level n (N = 2^n + 3 control points).
double olr_knot(int level, int k) {
  const int N = (1 << level) + 3;
  if (k <= 3) return 0;
  if (k >= N) return 1;
  return std::ldexp(static_cast<double>(k - 3), -level);
}

}  // namespace

GeodesicPath CurveTracer::path(const MeshPoint& a, const MeshPoint& b) {
  GeodesicPath p;
  ++stats.shortest_paths;
  if (!solver_.shortest_path(a, b, p, nullptr, search_)) {
    // Unreachable (another component): a degenerate path that stays at a.
    p = GeodesicPath{a, a, {a.face}, {}};
  }
  return p;
}

MeshPoint CurveTracer::average(const MeshPoint& a, const MeshPoint& b, double w) {
  if (w <= 0) return a;
  if (w >= 1) return b;
  return eval_path(solver_.mesh(), path(a, b), w);
}

void CurveTracer::append_path(const GeodesicPath& p, std::vector<MeshPoint>& polyline) {
  static thread_local std::vector<MeshPoint> points;
  path_points(solver_.mesh(), p, points);
  size_t first = 0;
  if (!polyline.empty() && same_point(solver_.mesh(), polyline.back(), points.front())) first = 1;
  polyline.insert(polyline.end(), points.begin() + first, points.end());
}

void CurveTracer::append_path(const MeshPoint& a, const MeshPoint& b, std::vector<MeshPoint>& polyline) {
  append_path(path(a, b), polyline);
}

// ---- RDC ----------------------------------------------------------------------------------------

CurveTracer::RdcNode CurveTracer::rdc_root(const ControlPolygon& polygon) {
  RdcNode node;
  for (int i = 0; i < 3; ++i) node.sides[i] = path(polygon[i], polygon[i + 1]);
  return node;
}

void CurveTracer::rdc_split(const RdcNode& node, RdcNode& left, RdcNode& right) {
  const TriMesh& mesh = solver_.mesh();
  const MeshPoint q0 = eval_path(mesh, node.sides[0], 0.5);
  const MeshPoint q1 = eval_path(mesh, node.sides[1], 0.5);
  const MeshPoint q2 = eval_path(mesh, node.sides[2], 0.5);
  const GeodesicPath q01 = path(q0, q1), q12 = path(q1, q2);
  const MeshPoint r0 = eval_path(mesh, q01, 0.5), r1 = eval_path(mesh, q12, 0.5);
  const GeodesicPath r01 = path(r0, r1);
  const double tm = 0.5 * (node.t0 + node.t1);
  left.sides = {sub_path(mesh, node.sides[0], 0, 0.5), sub_path(mesh, q01, 0, 0.5), sub_path(mesh, r01, 0, 0.5)};
  right.sides = {sub_path(mesh, r01, 0.5, 1), sub_path(mesh, q12, 0.5, 1), sub_path(mesh, node.sides[2], 0.5, 1)};
  left.t0 = node.t0, left.t1 = tm;
  right.t0 = tm, right.t1 = node.t1;
}

// Whether the polygon with these sides turns less than `angle` at both inner points.
bool CurveTracer::flat(const Sides& sides, double angle) {
  const TriMesh& mesh = solver_.mesh();
  for (int i = 0; i < 2; ++i) {
    const Tangent in = end_tangent(mesh, sides[i]);
    const Tangent out = start_tangent(mesh, sides[i + 1]);
    if (in.dir.norm() == 0 || out.dir.norm() == 0) continue;
    if (turning_angle(mesh, sides[i].end, in, out) >= angle) return false;
  }
  return true;
}

bool CurveTracer::rdc_stop(const RdcNode& node, int level, const TraceOptions& options) {
  if (!options.adaptive) return level >= options.levels;
  return level >= options.max_levels || flat(node.sides, options.angle);
}

template <class Leaf>
void CurveTracer::rdc_visit(const RdcNode& node, int level, const TraceOptions& options, Leaf&& leaf) {
  if (rdc_stop(node, level, options)) return leaf(node);
  RdcNode left, right;
  rdc_split(node, left, right);
  rdc_visit(left, level + 1, options, leaf);
  rdc_visit(right, level + 1, options, leaf);
}

CurveTracer::RdcNode CurveTracer::rdc_leaf(const ControlPolygon& polygon, double t, const TraceOptions& options) {
  RdcNode node = rdc_root(polygon);
  for (int level = 0; !rdc_stop(node, level, options); ++level) {
    RdcNode left, right;
    rdc_split(node, left, right);
    node = t <= left.t1 ? std::move(left) : std::move(right);
  }
  return node;
}

// ---- OLR ----------------------------------------------------------------------------------------

CurveTracer::Sides CurveTracer::sides_of(const std::array<MeshPoint, 4>& points) {
  return {path(points[0], points[1]), path(points[1], points[2]), path(points[2], points[3])};
}

// Points first .. first+count-1 of level+1 from the level's points and the paths between them,
// both indexed from global point `offset` (0 for a whole polygon, m for interval m's four points).
void CurveTracer::olr_points(int level, int N, const MeshPoint* points, const GeodesicPath* sides, int offset, int first,
                             int count, MeshPoint* out) {
  const TriMesh& mesh = solver_.mesh();
  auto pt = [&](int j) { return points[j - offset]; };
  auto avg = [&](int j, double w) { return eval_path(mesh, sides[j - offset], w); };
  auto mix = [&](const MeshPoint& x, const MeshPoint& y) { return average(x, y, 0.5); };
  for (int i = 0; i < count; ++i) out[i] = olr_point(level, N, first + i, pt, avg, mix);
}

void CurveTracer::olr_refine(const std::vector<MeshPoint>& old_points, int level, std::vector<MeshPoint>& out) {
  const int N = static_cast<int>(old_points.size());
  std::vector<GeodesicPath> sides(N - 1);
  for (int j = 0; j + 1 < N; ++j) sides[j] = path(old_points[j], old_points[j + 1]);
  out.resize(2 * N - 3);
  olr_points(level, N, old_points.data(), sides.data(), 0, 0, 2 * N - 3, out.data());
}

// Adaptive OLR stops at a node whose polygon is flat, never at the root (it is the Bézier polygon).
bool CurveTracer::olr_stop(const Sides& sides, int level, const TraceOptions& options) {
  return level >= options.max_levels || (level > 0 && flat(sides, options.angle));
}

void CurveTracer::olr_adaptive(const std::array<MeshPoint, 4>& points, int level, int interval,
                               const TraceOptions& options, std::vector<MeshPoint>& out) {
  const Sides sides = sides_of(points);
  if (olr_stop(sides, level, options)) {
    // A leaf adds its Bézier polygon (blossoms at its knots), so that neighbouring leaves of
    // different levels meet at a point of the curve with collinear handles. (§4.2.1 adds the
    // rightmost B-spline control point; across a change of level that point doubles back.)
    const ControlPolygon bezier = olr_bezier(points, sides, level, interval);
    out.insert(out.end(), bezier.begin() + (out.empty() ? 0 : 1), bezier.end());
    return;
  }
  // The five points of the two children (new indices 2m .. 2m+4).
  const int m = interval;
  std::array<MeshPoint, 5> next;
  olr_points(level, (1 << level) + 3, points.data(), sides.data(), m, 2 * m, 5, next.data());
  olr_adaptive({next[0], next[1], next[2], next[3]}, level + 1, 2 * m, options, out);
  olr_adaptive({next[1], next[2], next[3], next[4]}, level + 1, 2 * m + 1, options, out);
}

void CurveTracer::olr_leaf(const ControlPolygon& polygon, double t, const TraceOptions& options,
                           std::array<MeshPoint, 4>& points, Sides& sides, int& level, int& interval) {
  points = polygon;
  interval = 0;
  for (level = 0;; ++level) {
    sides = sides_of(points);
    if (options.adaptive ? olr_stop(sides, level, options) : level >= options.levels) return;
    const int m = interval;
    const int child = t <= std::ldexp(2.0 * m + 1, -(level + 1)) ? 0 : 1;
    std::array<MeshPoint, 4> next;
    olr_points(level, (1 << level) + 3, points.data(), sides.data(), m, 2 * m + child, 4, next.data());
    points = next;
    interval = 2 * m + child;
  }
}

// The Bézier polygon of interval m of level n: blossoms f(a,a,a), f(a,a,b), f(a,b,b), f(b,b,b) by the
// de Boor recurrence with manifold averages.
ControlPolygon CurveTracer::olr_bezier(const std::array<MeshPoint, 4>& points, const Sides& sides, int level, int m) {
  const TriMesh& mesh = solver_.mesh();
  const double a = olr_knot(level, m + 3), b = olr_knot(level, m + 4);
  auto blossom = [&](double x1, double x2, double x3) {
    const double xs[3] = {x1, x2, x3};
    std::array<MeshPoint, 4> d = points;
    for (int r = 1; r <= 3; ++r) {
      for (int i = 3; i >= r; --i) {
        const int I = m + i;
        const double lo = olr_knot(level, I), hi = olr_knot(level, I + 4 - r);
        const double alpha = hi > lo ? (xs[r - 1] - lo) / (hi - lo) : 0;
        // The first step averages consecutive control points: along the sides already known.
        d[i] = r == 1 ? (alpha <= 0 ? d[i - 1] : alpha >= 1 ? d[i] : eval_path(mesh, sides[i - 1], alpha))
                      : average(d[i - 1], d[i], alpha);
      }
    }
    return d[3];
  };
  return {blossom(a, a, a), blossom(a, a, b), blossom(a, b, b), blossom(b, b, b)};
}

// ---- Public -------------------------------------------------------------------------------------

void CurveTracer::subdivide(const ControlPolygon& polygon, const TraceOptions& options, std::vector<MeshPoint>& points) {
  search_ = options.search;
  points.assign(polygon.begin(), polygon.end());
  if (options.scheme == Scheme::kOLR) {
    if (options.adaptive) {
      points.clear();
      olr_adaptive(polygon, 0, 0, options, points);
      return;
    }
    std::vector<MeshPoint> next;
    for (int level = 0; level < options.levels; ++level) {
      olr_refine(points, level, next);
      points.swap(next);
    }
    return;
  }
  // The RDC polygon: the end points of every leaf's sides.
  points.clear();
  rdc_visit(rdc_root(polygon), 0, options, [&](const RdcNode& leaf) {
    if (points.empty()) points.push_back(leaf.sides[0].start);
    for (const GeodesicPath& side : leaf.sides) points.push_back(side.end);
  });
}

void CurveTracer::trace(const ControlPolygon& polygon, const TraceOptions& options, std::vector<MeshPoint>& polyline) {
  search_ = options.search;
  polyline.clear();
  if (options.scheme == Scheme::kRDC) {
    rdc_visit(rdc_root(polygon), 0, options, [&](const RdcNode& leaf) {
      for (const GeodesicPath& side : leaf.sides) append_path(side, polyline);
    });
    return;
  }
  subdivide(polygon, options, scratch_points_);
  for (size_t i = 0; i + 1 < scratch_points_.size(); ++i) append_path(scratch_points_[i], scratch_points_[i + 1], polyline);
}

MeshPoint CurveTracer::eval(const ControlPolygon& polygon, double t, const TraceOptions& options) {
  search_ = options.search;
  t = std::clamp(t, 0.0, 1.0);
  if (t == 0) return polygon[0];
  if (t == 1) return polygon[3];
  ControlPolygon leaf;
  double t0, t1;
  if (options.scheme == Scheme::kRDC) {
    const RdcNode node = rdc_leaf(polygon, t, options);
    leaf = {node.sides[0].start, node.sides[1].start, node.sides[2].start, node.sides[2].end};
    t0 = node.t0, t1 = node.t1;
  } else {
    std::array<MeshPoint, 4> points;
    Sides sides;
    int level, interval;
    olr_leaf(polygon, t, options, points, sides, level, interval);
    leaf = olr_bezier(points, sides, level, interval);
    t0 = olr_knot(level, interval + 3), t1 = olr_knot(level, interval + 4);
  }
  // Direct de Casteljau on the (short) leaf polygon.
  const double s = (t - t0) / (t1 - t0);
  const MeshPoint q0 = average(leaf[0], leaf[1], s), q1 = average(leaf[1], leaf[2], s), q2 = average(leaf[2], leaf[3], s);
  return average(average(q0, q1, s), average(q1, q2, s), s);
}

void CurveTracer::split_leaf(const ControlPolygon& polygon, const ControlPolygon& leaf, double t0, double t1, double t,
                             ControlPolygon& left, ControlPolygon& right) {
  const TriMesh& mesh = solver_.mesh();
  const double s = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  const MeshPoint q0 = average(leaf[0], leaf[1], s), q1 = average(leaf[1], leaf[2], s), q2 = average(leaf[2], leaf[3], s);
  const MeshPoint r0 = average(q0, q1, s), r1 = average(q1, q2, s);
  const MeshPoint pt = average(r0, r1, s);
  // Shoots from pt along the geodesic towards x (or away from it: sign -1) for `scale` times its length.
  auto shoot = [&](const MeshPoint& x, double sign, double scale, MeshPoint& out) {
    const GeodesicPath g = path(pt, x);
    Tangent dir = start_tangent(mesh, g);
    const double len = path_length(mesh, g) * scale;
    if (dir.dir.norm() == 0 || !(len > 0)) return false;
    dir.dir *= sign;
    StraightestGeodesic traced;
    straightest_geodesic(mesh, pt, dir, len, traced);
    out = traced.end;
    return true;
  };
  // The handles at pt: P̄2 extends pt->r0 to t/(t-t0) of its length, P̄'1 extends pt->r1 to
  // (1-t)/(t1-t). When t sits on a leaf's end one of r0, r1 coincides with pt: that handle then
  // goes opposite the other one, as collinear handles do.
  MeshPoint before = pt, after = pt;
  const bool has_before = t > t0 && shoot(r0, 1, t / (t - t0), before);
  const bool has_after = t1 > t && shoot(r1, 1, (1 - t) / (t1 - t), after);
  if (!has_after && t > t0) shoot(r0, -1, (1 - t) / (t - t0), after);
  if (!has_before && t1 > t) shoot(r1, -1, t / (t1 - t), before);
  left = {polygon[0], average(polygon[0], polygon[1], t), before, pt};
  right = {pt, after, average(polygon[2], polygon[3], t), polygon[3]};
}

void CurveTracer::split(const ControlPolygon& polygon, double t, const TraceOptions& options, ControlPolygon& left,
                        ControlPolygon& right) {
  search_ = options.search;
  t = std::clamp(t, 1e-6, 1 - 1e-6);
  if (options.scheme == Scheme::kRDC) {
    const RdcNode node = rdc_leaf(polygon, t, options);
    const ControlPolygon leaf = {node.sides[0].start, node.sides[1].start, node.sides[2].start, node.sides[2].end};
    split_leaf(polygon, leaf, node.t0, node.t1, t, left, right);
    return;
  }
  std::array<MeshPoint, 4> points;
  Sides sides;
  int level, interval;
  olr_leaf(polygon, t, options, points, sides, level, interval);
  split_leaf(polygon, olr_bezier(points, sides, level, interval), olr_knot(level, interval + 3), olr_knot(level, interval + 4), t,
             left, right);
}

}  // namespace splinekit::surface
