// Cubic Bézier curves on meshes by subdivision (b/Surf §3.5–§4), built from the manifold average
// A(P, Q; w) = γ_PQ(w), the point at fraction w of the shortest path from P to Q (§3.2, eq. 4).
//   - RDC: recursive de Casteljau bisection (§3.5, §4.1): each step computes three shortest paths and
//     splits the polygon into two sub-polygons made of halves of existing paths.
//   - OLR: open-uniform Lane–Riesenfeld (§3.6, §4.2): midpoint insertion plus two smoothing steps,
//     factored into pairwise averages (eq. 9 in the middle, eq. 10 at the ends, and the special
//     stencils of the first two levels derived from Boehm knot insertion on the knot vector
//     0000 1111).
// Both trace uniformly (a fixed number of levels) or adaptively (stop where consecutive geodesic
// segments of the polygon turn by less than an angle; adaptive OLR traces the Bézier polygons of its
// leaves, see olr_adaptive_polygon), evaluate a point at t, and split a curve at t into two curves
// that interpolate its ends and the split point with the same tangents (§4.1.3).
#pragma once

#include "surface/geodesic.h"

#include <array>
#include <vector>

namespace splinekit::surface {

enum class Scheme { kRDC, kOLR };

// Uniform subdivision levels when TraceOptions::levels is left unset: 5 for OLR (35 points), 4 for
// RDC (48 geodesic segments). The package's DEFAULT_TRACE_LEVELS (src/surface/trace-options.ts)
// states the same numbers; tests/unit/surface-trace-defaults.test.ts holds them equal.
constexpr int default_levels(Scheme scheme) { return scheme == Scheme::kOLR ? 5 : 4; }

struct TraceOptions {
  Scheme scheme = Scheme::kOLR;
  bool adaptive = false;
  int levels = -1;                          // uniform subdivision levels; negative: default_levels(scheme)
  double angle = 0.0872664626;              // adaptive threshold (radians; 5°)
  int max_levels = 10;                      // adaptive recursion bound (resolves cusps)
  SearchGraph search = SearchGraph::kDual;  // phase (i) graph of every shortest path (geodesic_options.h)

  // The uniform levels in effect: `levels`, or the scheme's default when unset.
  int uniform_levels() const { return levels >= 0 ? levels : default_levels(scheme); }
};

using ControlPolygon = std::array<MeshPoint, 4>;

struct TraceStats {
  int shortest_paths = 0;     // searched (phase (i) on the graph)
  int seeded_paths = 0;       // straightened through known paths instead
  int unreachable_paths = 0;  // between points on parts of the mesh that are not connected (a
                              // path that stays at its start stands in: the curve is not whole)
  PathStats paths;            // the counters of all of them (search, strips, passes, flips)
};

class CurveTracer {
 public:
  explicit CurveTracer(GeodesicSolver& solver) : solver_(solver) {}

  // The curve as a polyline on the mesh: P0, every point and edge crossing along the way, P3.
  // Consecutive points share a face.
  void trace(const ControlPolygon& polygon, const TraceOptions& options, std::vector<MeshPoint>& polyline);
  // The subdivided control polygon (its points; consecutive ones joined by shortest paths).
  void subdivide(const ControlPolygon& polygon, const TraceOptions& options, std::vector<MeshPoint>& points);
  // The point at parameter t.
  MeshPoint eval(const ControlPolygon& polygon, double t, const TraceOptions& options);
  // Point insertion: two polygons (P0, ·, ·, P_t) and (P_t, ·, ·, P3).
  void split(const ControlPolygon& polygon, double t, const TraceOptions& options, ControlPolygon& left,
             ControlPolygon& right);

  GeodesicSolver& solver() { return solver_; }
  TraceStats stats;

 private:
  GeodesicPath path(const MeshPoint& a, const MeshPoint& b);
  SearchGraph search_ = SearchGraph::kDual;
  MeshPoint average(const MeshPoint& a, const MeshPoint& b, double w);

  using Sides = std::array<GeodesicPath, 3>;  // shortest paths between consecutive control points
  // Whether the polygon of three consecutive sides turns by less than `angle` at both joints.
  bool flat(const GeodesicPath& s0, const GeodesicPath& s1, const GeodesicPath& s2, double angle);
  bool flat(const Sides& sides, double angle) { return flat(sides[0], sides[1], sides[2], angle); }

  // RDC
  struct RdcNode {
    Sides sides;
    double t0 = 0, t1 = 1;
  };
  RdcNode rdc_root(const ControlPolygon& polygon);
  void rdc_split(const RdcNode& node, RdcNode& left, RdcNode& right);
  bool rdc_stop(const RdcNode& node, int level, const TraceOptions& options);
  // Calls leaf(node) on the leaves of the recursion, left to right.
  template <class Leaf>
  void rdc_visit(const RdcNode& node, int level, const TraceOptions& options, Leaf&& leaf);
  RdcNode rdc_leaf(const ControlPolygon& polygon, double t, const TraceOptions& options);

  // Seeded paths. Every point a subdivision step makes lies on the previous polygon's shortest paths
  // (at fraction w of side `side`) or on a path from such a point (`detour`, from there to the
  // point). The path between two such points is first tried through those paths (a strip without a
  // search, geodesic.h straighten_through), which is what makes deep levels cheap; the search is
  // kept where the detour would sweep a large area (see seed_or_search).
  struct Located {
    MeshPoint point;
    int side = -1;  // -1: not on a known polygon (the control points): searched
    double w = 0;
    GeodesicPath detour;
  };
  static Located unseeded(const MeshPoint& p) { return {p, -1, 0, {}}; }
  // Whether x's place on the polygon comes strictly before y's.
  static bool comes_before(const Located& x, const Located& y) {
    return x.side < y.side || (x.side == y.side && x.w < y.w);
  }
  // The path from x to y; `sides` are the polygon's sides that x.side and y.side index (from `offset`).
  GeodesicPath path_between(const Located& x, const Located& y, const GeodesicPath* sides, int offset);
  GeodesicPath seed_or_search(const std::vector<GeodesicPath>& pieces);
  double mean_face_area();

  // OLR
  Sides sides_of(const std::array<MeshPoint, 4>& points);
  void olr_points(int level, int N, const Located* points, const GeodesicPath* sides, int offset, int first, int count,
                  Located* out);
  // The polygon after `levels` uniform steps and the shortest paths between its points.
  void olr_uniform(const ControlPolygon& polygon, int levels, std::vector<Located>& points,
                   std::vector<GeodesicPath>& sides);
  bool olr_stop(const Sides& sides, int level, const TraceOptions& options);
  void olr_leaf(const ControlPolygon& polygon, double t, const TraceOptions& options, std::array<MeshPoint, 4>& points,
                Sides& sides, int& level, int& interval);
  // A leaf of the adaptive expansion tree, as its Bézier polygon needs it: the leaf's knot interval
  // [a, b], its inner Bézier points f(a,a,b) and f(a,b,b), which lie on its middle side (the piece of
  // that side between them), and the outer sides where the leaf ends the curve.
  struct OlrLeaf {
    double a = 0, b = 1;
    GeodesicPath inner;  // f(a,a,b) -> f(a,b,b), along the leaf's side P1 -> P2
    GeodesicPath joint;  // from the previous leaf's f(a',a,a) to f(a,a,b), through f(a,a,a); empty for the first
    GeodesicPath first;  // when a = 0: side P0 -> P1 (P1 = f(0,0,b)); else empty
    GeodesicPath last;   // when b = 1: side P2 -> P3 (P2 = f(a,1,1)); else empty
  };
  // The leaves below a node, left to right. `parent`: the sides of the polygon `points` were made
  // from, indexed from parent_offset (null for the root, whose points are unseeded).
  void olr_adaptive(const std::array<Located, 4>& points, const GeodesicPath* parent, int parent_offset, int level,
                    int interval, const TraceOptions& options, std::vector<OlrLeaf>& leaves);
  // Node m of `level` (its sides) as the leaf after `leaves`; false when it must be expanded instead.
  bool olr_make_leaf(Sides& sides, int level, int m, const TraceOptions& options, const std::vector<OlrLeaf>& leaves,
                     OlrLeaf& leaf);
  // The adaptive output: the leaves' Bézier polygons joined into one, as its 3·#leaves geodesic segments.
  void olr_adaptive_polygon(const ControlPolygon& polygon, const TraceOptions& options,
                            std::vector<GeodesicPath>& segments);
  ControlPolygon olr_bezier(const std::array<MeshPoint, 4>& points, const Sides& sides, int level, int interval);

  void append_path(const GeodesicPath& p, std::vector<MeshPoint>& polyline);
  void split_leaf(const ControlPolygon& polygon, const ControlPolygon& leaf, double t0, double t1, double t,
                  ControlPolygon& left, ControlPolygon& right);

  GeodesicSolver& solver_;
  double mean_face_area_ = -1;
  std::vector<OlrLeaf> scratch_leaves_;
  std::vector<GeodesicPath> scratch_segments_;
};

}  // namespace splinekit::surface
