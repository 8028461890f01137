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
auto olr_point(int level, int N, int i, Pt pt, Avg avg, Mix mix) -> decltype(pt(0)) {
  const int M = 2 * N - 3;
  if (level == 0) {  // Bézier halves as a B-spline: P0, midpoints, P3
    if (i == 0) return pt(0);
    if (i == 4) return pt(3);
    return avg(i - 1, 0.5);
  }
  if (level == 1) {  // knots 0000 ½ 1111 -> 0000 ¼ ½ ¾ 1111 (Boehm): 3/16 10/16 3/16 in the middle
    switch (i) {
      case 0:
        return pt(0);
      case 1:
        return avg(0, 0.5);
      case 2:
        return avg(1, 0.25);
      case 3:
        return mix(avg(1, 0.625), avg(2, 0.375));
      case 4:
        return avg(2, 0.75);
      case 5:
        return avg(3, 0.5);
      default:
        return pt(4);
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
  if (!solver_.shortest_path(a, b, p, &stats.paths, search_)) {
    // Unreachable (another component): a degenerate path that stays at a (counted: the caller
    // tells the user the curve cannot be traced).
    ++stats.unreachable_paths;
    p = GeodesicPath{a, a, {a.face}, {}, {}};
  }
  return p;
}

double CurveTracer::mean_face_area() {
  if (mean_face_area_ < 0) {
    const TriMesh& mesh = solver_.mesh();
    double total = 0;
    for (const auto& t : mesh.triangles)
      total +=
          (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm() / 2;
    mean_face_area_ = mesh.triangles.empty() ? 0 : total / static_cast<double>(mesh.triangles.size());
  }
  return mean_face_area_;
}

// Straightening a strip through the pieces sweeps the path across the region between the pieces and
// the geodesic: cheap when the pieces nearly line up (the polygons of deep levels, short detours),
// costlier and more likely to settle on a longer local geodesic when they turn sharply around a far
// corner (the first levels of a large control polygon), where the search finds a closer strip. The
// region is estimated by the fan of triangles from the start over the points where pieces meet.
// Measured on random whole-surface polygons of nefertiti and spot_loop2_369k: a bound of 64 mean
// faces seeds about 80% of the paths, and seeded paths came out shorter than searched ones more often
// than longer; larger bounds seed more without being faster (also with chords, 2026-12-01: 128 to
// 1024 on spot_loop2_369k within 4%), and the curves of nefertiti grow longer (0.4% at 128, 8% at 1024).
// The fan is measured in space, which on a coil or a fold (pieces that run along the surface far from
// the start in space) is large however well the pieces line up; there the region is also estimated
// from the surface: a triangle with two sides of half the pieces' total length L over a base of d,
// a lower bound on the distance between the ends (the larger of the Euclidean distance and 0.9 times
// the landmark bound, landmarks.h), area d·sqrt(L² − d²)/4; the smaller estimate decides.
// The seeded straightening gets at most 256 passes, and where it needs more, the search takes over:
// the estimates go by area, and where the pieces pass by a point that small faces fan around (a graded
// mesh, a pole), a thin region holds thousands of vertices, each flipped in turn (a polygon of such a
// disc, not tuned on: one second-level path took 5,942 passes, 132 ms, where the search's took 26
// passes, 1.3 ms, to the same path; on the benchmark's meshes no seeded path took more than 256,
// 2026-12-05).
GeodesicPath CurveTracer::seed_or_search(const std::vector<GeodesicPath>& pieces) {
  constexpr double kSeedFaces = 64;
  constexpr int kSeedPasses = 256;
  const TriMesh& mesh = solver_.mesh();
  const MeshPoint& a = pieces.front().start;
  const MeshPoint& b = pieces.back().end;
  const Vec3 pa = eval_position(mesh, a);
  double area = 0;
  Vec3 prev = eval_position(mesh, pieces.front().end);
  for (size_t k = 1; k < pieces.size(); ++k) {
    const Vec3 next = eval_position(mesh, pieces[k].end);
    area += (prev - pa).cross(next - pa).norm() / 2;
    prev = next;
  }
  const Landmarks& landmarks = solver_.landmarks();
  if (!landmarks.empty() && area > kSeedFaces * mean_face_area()) {
    double L = 0;
    for (const GeodesicPath& piece : pieces) L += path_length(mesh, piece);
    const double d = std::max((eval_position(mesh, b) - pa).norm(), 0.9 * landmarks.bound_between(a.face, b.face));
    area = std::min(area, d * std::sqrt(std::max(0.0, L * L - d * d)) / 4);
  }
  GeodesicPath p;
  if (area <= kSeedFaces * mean_face_area() && solver_.straighten_through(pieces, p, &stats.paths, kSeedPasses)) {
    ++stats.seeded_paths;
    return p;
  }
  return path(a, b);
}

GeodesicPath CurveTracer::path_between(const Located& x, const Located& y, const GeodesicPath* sides, int offset) {
  if (x.side < 0 || y.side < 0) return path(x.point, y.point);
  const TriMesh& mesh = solver_.mesh();
  static thread_local std::vector<GeodesicPath> pieces;
  pieces.clear();
  if (!x.detour.strip.empty()) pieces.push_back(reversed(mesh, x.detour));
  // Along the polygon's sides from x's place to y's (backwards when y comes first).
  const bool forward = !comes_before(y, x);
  const Located& lo = forward ? x : y;
  const Located& hi = forward ? y : x;
  const size_t first = pieces.size();
  for (int j = lo.side; j <= hi.side; ++j)
    pieces.push_back(sub_path(mesh, sides[j - offset], j == lo.side ? lo.w : 0, j == hi.side ? hi.w : 1));
  if (!forward) {
    std::reverse(pieces.begin() + first, pieces.end());
    for (size_t k = first; k < pieces.size(); ++k) pieces[k] = reversed(mesh, pieces[k]);
  }
  if (!y.detour.strip.empty()) pieces.push_back(y.detour);
  GeodesicPath p = seed_or_search(pieces);
  pieces.clear();  // (their strips are not kept alive between traces)
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

// ---- RDC ----------------------------------------------------------------------------------------

CurveTracer::RdcNode CurveTracer::rdc_root(const ControlPolygon& polygon) {
  RdcNode node;
  for (int i = 0; i < 3; ++i) node.sides[i] = path(polygon[i], polygon[i + 1]);
  return node;
}

void CurveTracer::rdc_split(const RdcNode& node, RdcNode& left, RdcNode& right) {
  const TriMesh& mesh = solver_.mesh();
  // The midpoints q0, q1, q2 of the sides, then r0, r1 of the paths q0q1 and q1q2, then r0r1: each
  // new path is seeded through the halves of the two it joins (they meet at a control point).
  const GeodesicPath q01 =
      seed_or_search({sub_path(mesh, node.sides[0], 0.5, 1), sub_path(mesh, node.sides[1], 0, 0.5)});
  const GeodesicPath q12 =
      seed_or_search({sub_path(mesh, node.sides[1], 0.5, 1), sub_path(mesh, node.sides[2], 0, 0.5)});
  const GeodesicPath r01 = seed_or_search({sub_path(mesh, q01, 0.5, 1), sub_path(mesh, q12, 0, 0.5)});
  const double tm = 0.5 * (node.t0 + node.t1);
  left.sides = {sub_path(mesh, node.sides[0], 0, 0.5), sub_path(mesh, q01, 0, 0.5), sub_path(mesh, r01, 0, 0.5)};
  right.sides = {sub_path(mesh, r01, 0.5, 1), sub_path(mesh, q12, 0.5, 1), sub_path(mesh, node.sides[2], 0.5, 1)};
  left.t0 = node.t0, left.t1 = tm;
  right.t0 = tm, right.t1 = node.t1;
}

// Whether the polygon with these sides turns less than `angle` at both inner points.
bool CurveTracer::flat(const GeodesicPath& s0, const GeodesicPath& s1, const GeodesicPath& s2, double angle) {
  const TriMesh& mesh = solver_.mesh();
  const GeodesicPath* sides[3] = {&s0, &s1, &s2};
  for (int i = 0; i < 2; ++i) {
    const Tangent in = end_tangent(mesh, *sides[i]);
    const Tangent out = start_tangent(mesh, *sides[i + 1]);
    if (in.dir.norm() == 0 || out.dir.norm() == 0) continue;
    if (turning_angle(mesh, sides[i]->end, in, out) >= angle) return false;
  }
  return true;
}

bool CurveTracer::rdc_stop(const RdcNode& node, int level, const TraceOptions& options) {
  if (!options.adaptive) return level >= options.uniform_levels();
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
// The new points are located on those paths (their `side` is a global index).
void CurveTracer::olr_points(int level, int N, const Located* points, const GeodesicPath* sides, int offset, int first,
                             int count, Located* out) {
  const TriMesh& mesh = solver_.mesh();
  auto pt = [&](int j) {
    return j + 1 < N ? Located{points[j - offset].point, j, 0, {}} : Located{points[j - offset].point, j - 1, 1, {}};
  };
  auto avg = [&](int j, double w) { return Located{eval_path(mesh, sides[j - offset], w), j, w, {}}; };
  // The midpoint of the path between x and y, located from whichever of them comes first.
  auto mix = [&](const Located& x, const Located& y) {
    const GeodesicPath between = path_between(x, y, sides, offset);
    const bool x_first = !comes_before(y, x);
    Located m{{}, x_first ? x.side : y.side, x_first ? x.w : y.w, {}};
    m.detour = x_first ? sub_path(mesh, between, 0, 0.5) : reversed(mesh, sub_path(mesh, between, 0.5, 1));
    m.point = m.detour.end;  // the midpoint
    return m;
  };
  for (int i = 0; i < count; ++i) out[i] = olr_point(level, N, first + i, pt, avg, mix);
}

void CurveTracer::olr_uniform(const ControlPolygon& polygon, int levels, std::vector<Located>& points,
                              std::vector<GeodesicPath>& sides) {
  points.clear();
  for (const MeshPoint& p : polygon) points.push_back(unseeded(p));
  const Sides first = sides_of(polygon);
  sides.assign(first.begin(), first.end());
  std::vector<Located> next;
  std::vector<GeodesicPath> next_sides;
  for (int level = 0; level < levels; ++level) {
    const int N = static_cast<int>(points.size());
    next.resize(2 * N - 3);
    olr_points(level, N, points.data(), sides.data(), 0, 0, 2 * N - 3, next.data());
    next_sides.resize(next.size() - 1);
    for (size_t i = 0; i + 1 < next.size(); ++i) next_sides[i] = path_between(next[i], next[i + 1], sides.data(), 0);
    points.swap(next);
    sides.swap(next_sides);
  }
}

// Adaptive OLR stops at a node whose polygon is flat, never at the root (it is the Bézier polygon).
bool CurveTracer::olr_stop(const Sides& sides, int level, const TraceOptions& options) {
  return level >= options.max_levels || (level > 0 && flat(sides, options.angle));
}

// The node's B-spline segment over [a, b] = [u_{m+3}, u_{m+4}] has control points
// P_{m+i} = f(u_{m+i+1}, u_{m+i+2}, u_{m+i+3}); its inner Bézier points f(a,a,b) and f(a,b,b) differ from
// P_{m+1} = f(u_{m+2},a,b) and P_{m+2} = f(a,b,u_{m+5}) in one argument only, so they lie on the side
// P_{m+1} -> P_{m+2}, at fractions (a - u_{m+2}) / (u_{m+5} - u_{m+2}) and (b - u_{m+2}) / (u_{m+5} - u_{m+2})
// (the B-spline to Bézier conversion, one average each).
//
// On a mesh the polygon traced is the Bézier one, which turns at its inner points by other angles
// than the B-spline polygon at its own; a node whose B-spline polygon is flat becomes a leaf only
// when the Bézier polygon is flat where it is known: at f(a,a,b), after the joint from the previous
// leaf (or side P0 -> P1 at the curve's start); at f(a,b,b), before the joint to the next leaf, which
// is estimated by the path to f(b,b,u_{m+5}) on side P_{m+2} -> P_{m+3} (the next leaf's f(b,b,c) when
// it has this level; side P2 -> P3 itself at the curve's end). The previous leaf's f(a',a,a) must also
// turn less into the joint. Below max_levels a node failing these is expanded instead.
bool CurveTracer::olr_make_leaf(Sides& sides, int level, int m, const TraceOptions& options,
                                const std::vector<OlrLeaf>& leaves, OlrLeaf& leaf) {
  const TriMesh& mesh = solver_.mesh();
  const double u2 = olr_knot(level, m + 2), u5 = olr_knot(level, m + 5), u6 = olr_knot(level, m + 6);
  leaf.a = olr_knot(level, m + 3), leaf.b = olr_knot(level, m + 4);
  leaf.inner = sub_path(mesh, sides[1], (leaf.a - u2) / (u5 - u2), (leaf.b - u2) / (u5 - u2));
  if (!leaves.empty()) leaf.joint = path(leaves.back().inner.end, leaf.inner.start);
  if (level < options.max_levels) {
    GeodesicPath ahead;
    if (leaf.b != 1) ahead = path(leaf.inner.end, eval_path(mesh, sides[2], (leaf.b - leaf.a) / (u6 - leaf.a)));
    const GeodesicPath& after = leaf.b == 1 ? sides[2] : ahead;
    if (!flat(leaves.empty() ? sides[0] : leaf.joint, leaf.inner, after, options.angle)) return false;
    if (!leaves.empty() && !flat(leaves.back().inner, leaf.joint, leaf.inner, options.angle)) return false;
  }
  if (leaf.a == 0) leaf.first = std::move(sides[0]);  // f(0,0,0) = P0, f(0,0,b) = P1
  if (leaf.b == 1) leaf.last = std::move(sides[2]);   // f(a,1,1) = P_{m+2}, f(1,1,1) = P_{m+3}
  return true;
}

void CurveTracer::olr_adaptive(const std::array<Located, 4>& points, const GeodesicPath* parent, int parent_offset,
                               int level, int interval, const TraceOptions& options, std::vector<OlrLeaf>& leaves) {
  Sides sides;  // (the root's points are unseeded: searched)
  for (int k = 0; k < 3; ++k) sides[k] = path_between(points[k], points[k + 1], parent, parent_offset);
  const int m = interval;
  if (olr_stop(sides, level, options)) {
    OlrLeaf leaf;
    if (olr_make_leaf(sides, level, m, options, leaves, leaf)) return leaves.push_back(std::move(leaf));
  }
  // The five points of the two children (new indices 2m .. 2m+4).
  std::array<Located, 5> next;
  olr_points(level, (1 << level) + 3, points.data(), sides.data(), m, 2 * m, 5, next.data());
  olr_adaptive({next[0], next[1], next[2], next[3]}, sides.data(), m, level + 1, 2 * m, options, leaves);
  olr_adaptive({next[1], next[2], next[3], next[4]}, sides.data(), m, level + 1, 2 * m + 1, options, leaves);
}

// b/Surf §4.2.1 emits the leftmost leaf's B-spline points and then the rightmost B-spline point of
// every further leaf. That is the subdivided B-spline polygon where all leaves share one level, but
// where the level rises from n to n+1 the next leaf's rightmost point P^{n+1}_{2m+5} has the Greville
// abscissa of the point just emitted, P^n_{m+3}, and lies beside it: the polygon steps back (turns up
// to 180°, on the plane too). Instead every leaf contributes its Bézier polygon, so that leaves of any
// levels meet at a point of the curve: the inner points on the leaf's middle side (olr_adaptive), and
// between leaves [a, b] and [b, c] the joint f(b,b,b), which lies on the path from the left leaf's
// f(a,b,b) to the right leaf's f(b,b,c) at fraction (b - a) / (c - a). Consecutive Bézier points are
// thus joined by pieces of known paths (the two sides at the curve's ends, the middle sides, and one
// path per joint, in which the joint's two handles are collinear; olr_make_leaf).
void CurveTracer::olr_adaptive_polygon(const ControlPolygon& polygon, const TraceOptions& options,
                                       std::vector<GeodesicPath>& segments) {
  const TriMesh& mesh = solver_.mesh();
  std::vector<OlrLeaf>& leaves = scratch_leaves_;
  leaves.clear();
  olr_adaptive({unseeded(polygon[0]), unseeded(polygon[1]), unseeded(polygon[2]), unseeded(polygon[3])}, nullptr, 0, 0,
               0, options, leaves);
  segments.clear();
  segments.push_back(std::move(leaves.front().first));
  for (size_t k = 0; k < leaves.size(); ++k) {
    segments.push_back(std::move(leaves[k].inner));
    if (k + 1 == leaves.size()) break;
    const double w = (leaves[k].b - leaves[k].a) / (leaves[k + 1].b - leaves[k].a);
    const GeodesicPath& joint = leaves[k + 1].joint;
    segments.push_back(sub_path(mesh, joint, 0, w));
    segments.push_back(sub_path(mesh, joint, w, 1));
  }
  segments.push_back(std::move(leaves.back().last));
  leaves.clear();  // (their strips are not kept alive between traces)
}

void CurveTracer::olr_leaf(const ControlPolygon& polygon, double t, const TraceOptions& options,
                           std::array<MeshPoint, 4>& points, Sides& sides, int& level, int& interval) {
  points = polygon;
  interval = 0;
  for (level = 0;; ++level) {
    sides = sides_of(points);
    if (options.adaptive ? olr_stop(sides, level, options) : level >= options.uniform_levels()) return;
    const int m = interval;
    const int child = t <= std::ldexp(2.0 * m + 1, -(level + 1)) ? 0 : 1;
    std::array<Located, 4> here, next;
    for (int k = 0; k < 4; ++k) here[k] = unseeded(points[k]);
    olr_points(level, (1 << level) + 3, here.data(), sides.data(), m, 2 * m + child, 4, next.data());
    for (int k = 0; k < 4; ++k) points[k] = next[k].point;
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
        d[i] = r == 1 ? (alpha <= 0   ? d[i - 1]
                         : alpha >= 1 ? d[i]
                                      : eval_path(mesh, sides[i - 1], alpha))
                      : average(d[i - 1], d[i], alpha);
      }
    }
    return d[3];
  };
  return {blossom(a, a, a), blossom(a, a, b), blossom(a, b, b), blossom(b, b, b)};
}

// ---- Public -------------------------------------------------------------------------------------

void CurveTracer::subdivide(const ControlPolygon& polygon, const TraceOptions& options,
                            std::vector<MeshPoint>& points) {
  search_ = options.search;
  points.clear();
  if (options.scheme == Scheme::kOLR) {
    if (options.adaptive) {
      olr_adaptive_polygon(polygon, options, scratch_segments_);
      points.push_back(scratch_segments_.front().start);
      for (const GeodesicPath& segment : scratch_segments_) points.push_back(segment.end);
      scratch_segments_.clear();
      return;
    }
    std::vector<Located> located;
    std::vector<GeodesicPath> sides;
    olr_uniform(polygon, options.uniform_levels(), located, sides);
    for (const Located& p : located) points.push_back(p.point);
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
  if (!options.adaptive) {  // the last level's sides are the curve
    std::vector<Located> points;
    std::vector<GeodesicPath> sides;
    olr_uniform(polygon, options.uniform_levels(), points, sides);
    for (const GeodesicPath& side : sides) append_path(side, polyline);
    return;
  }
  olr_adaptive_polygon(polygon, options, scratch_segments_);
  for (const GeodesicPath& segment : scratch_segments_) append_path(segment, polyline);
  scratch_segments_.clear();
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
  const MeshPoint q0 = average(leaf[0], leaf[1], s), q1 = average(leaf[1], leaf[2], s),
                  q2 = average(leaf[2], leaf[3], s);
  return average(average(q0, q1, s), average(q1, q2, s), s);
}

void CurveTracer::split_leaf(const ControlPolygon& polygon, const ControlPolygon& leaf, double t0, double t1, double t,
                             ControlPolygon& left, ControlPolygon& right) {
  const TriMesh& mesh = solver_.mesh();
  const double s = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  const MeshPoint q0 = average(leaf[0], leaf[1], s), q1 = average(leaf[1], leaf[2], s),
                  q2 = average(leaf[2], leaf[3], s);
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
  split_leaf(polygon, olr_bezier(points, sides, level, interval), olr_knot(level, interval + 3),
             olr_knot(level, interval + 4), t, left, right);
}

}  // namespace splinekit::surface
