// Phase (iii) of a locally shortest path: straightening a strip of faces by flips at the reflex
// vertices of its funnel path, after
//   - Xin & Wang, "Efficiently determining a locally exact shortest path on polyhedral surfaces",
//     Computer-Aided Design 39(12), 2007: the vertex where the path bends has its semi-star in the
//     strip replaced by its other semi-star; if the path does not get shorter the vertex is frozen;
//   - Mancinelli, Nazzaro, Pellacini, Puppo, "b/Surf: interactive Bézier splines on surface meshes",
//     §5.1 "Point-to-point shortest path", which starts it from the funnel path (funnel.h) of a strip
//     found on the dual graph (dual_search.h).
// Three kinds of flip, each a named step below: the semi-star (`flip`), the zipper (`zipper`: the
// semi-stars of a line of boundary vertices that would still block the path, at once) and the
// chord (`chord`: the faces along the straight line between the neighbouring apices, which crosses
// many rows of vertices at once). A fourth step, the slide (`slide`), makes a zipper that runs past
// the neighbouring apices where the path would otherwise slide along a row of saddle vertices one
// vertex per pass. A fifth, the span (`span_pass`), is a chord across a run of bends at once where
// none of them can stay (vertices of angle sum at most 2π: convex or flat), from the apex before the
// run to the one after it: across long thin faces the flips move the strip a row at a time, and
// the bends slide across the rows a vertex per pass. A sixth, the glide (`glide`), makes a zipper
// along a row of saddle vertices the path does not touch, to where a bend pressed against it fades.
// A pass (`pass`) tries the spans first, else flips every reflex vertex whose faces do not touch
// another's and keeps the flips (`apply`) if the path gets shorter. A vertex is frozen up to the
// turn the path made there (looked at again when the path turns more there, as after its
// neighbours' flips), so that the path ends locally shortest: at every bend its angle on the far
// side is at least π. The straightening ends when no reflex vertex is left unfrozen, or after
// options.max_passes passes.
//
// A pass costs what the strip costs (its layout is moved and its funnel path copied past every
// change), while most of a long path's passes flip a few vertices in a few places (bends sliding
// along rows of saddle vertices one vertex per pass or two). Such a pass straightens each place as a
// strip of its own instead (`windowed_pass`): the faces between two bends of the path some way
// before and after it, with those bends as its end points, to the end; the windows' strips then
// replace their faces at once, as one pass's chords would.
//
// A Straightener belongs to one mesh; its scratch (strips, layouts, funnel paths, flips) is kept
// between paths, so after warm-up a path allocates nothing but what its result needs.
#pragma once

#include "surface/funnel.h"
#include "surface/geodesic_options.h"
#include "surface/path.h"
#include "surface/unfold.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace splinekit::surface {

// ---- Vertex stars -------------------------------------------------------------------------------

// Whether `face` has vertex v among its corners.
inline bool contains_vertex(const TriMesh& mesh, int face, int v) { return corner_of(mesh, face, v) >= 0; }
// The angle of `face` at its vertex v (radians).
double corner_angle(const TriMesh& mesh, int face, int v);
// The edge of `face` at its vertex v that a walk around v crosses to keep v on its left (or right).
inline int edge_around(const TriMesh& mesh, int face, int v, bool keep_left) {
  const int k = corner_of(mesh, face, v);
  return keep_left ? (k + 2) % 3 : k;
}

// ---- Flips --------------------------------------------------------------------------------------

// A change of the strip at apex `vertex`: strip[first + 1 .. last - 1] becomes `other`.
struct Flip {
  int first = 0, last = 0, vertex = -1;
  double turn = 0;                        // the path's turning angle at the vertex (radians)
  std::vector<int> other;                 // the faces that replace the strip's between first and last
  std::vector<std::array<Vec2, 3>> laid;  // a chord's: where its trace laid `other` (the strip's layout)
  bool chain = false, chord = false;      // a zipper's / a chord's (else a semi-star's)
};

// The strip faces a chord at apex j may replace: from the first face around apex j-1 (p_first) to
// the last around apex j+1 (q_last; q_first: the first around it). For an end point instead of a
// vertex: the strip's first (or last) face.
struct ChordRoom {
  int p_first = 0, q_first = 0, q_last = 0;
};

// Mesh vertices with a number each (open addressing): a path's frozen vertices and the like, found
// in O(1) however many there are; clearing costs what was put in, and after warm-up nothing is
// allocated.
class VertexSet {
 public:
  // v's number, or null when v is not in.
  const double* find(int v) const {
    if (slots_.empty()) return nullptr;
    for (size_t i = slot(v);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i] == v) return &values_[i];
      if (slots_[i] < 0) return nullptr;
    }
  }
  bool contains(int v) const { return find(v) != nullptr; }
  // Puts v in with `value` (or gives it that value).
  void insert(int v, double value = 0);
  void clear();
  size_t size() const { return keys_.size(); }

 private:
  size_t slot(int v) const { return (static_cast<size_t>(v) * 0x9E3779B1u) & (slots_.size() - 1); }
  std::vector<int> slots_, keys_;  // slots_: a power of two of them, -1 when free
  std::vector<double> values_;     // per slot
};

class Straightener {
 public:
  // ---- Constructors ----
  // For paths on `mesh` (which must outlive it). face_marks: #F or more entries, -1 everywhere
  // (DualSearch::face_marks(), shared so the mesh pays for one such table); left so between calls.
  Straightener(const TriMesh& mesh, std::vector<int>& face_marks, const ShortestPathOptions& options = {});

  // ---- Options ----
  // Reads straighten, chords, chord_min_turn and max_passes.
  ShortestPathOptions options;

  // ---- The whole straightening ----
  // Phases (ii)+(iii) on `strip` (consecutive faces adjacent; a on strip.front(), b on strip.back()):
  // `path` is the straightened path, `strip` its strip. Adds its flips and frozen vertices to stats.
  // At most `max_passes` passes (options.max_passes when negative); false when they ran out before
  // the path was locally shortest (`path` is then the path after the last of them).
  bool straighten(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, GeodesicPath& path,
                  PathStats* stats = nullptr, int max_passes = -1);

  // ---- Queries: the strip being straightened ----
  const std::vector<int>& strip() const { return path_.strip; }
  const UnfoldedStrip& unfolded() const { return path_.unfolded; }
  // Its funnel path (apices where it goes straight on dropped) and that path's length in the plane.
  const std::vector<Apex>& apices() const { return path_.apices; }
  double length() const { return path_.length; }
  // The faces of the strip around vertex v, from the face at index `at` (clamped to the strip):
  // strip[first..last], or false when that face does not hold v.
  bool run_of(int v, int at, int& first, int& last) const;
  // Whether no locally shortest path bends at vertex v: its angle sum is at most 2π (to rounding;
  // the far side of a bend there spans less than π), as on a convex or flat stretch. False for a
  // saddle (angle sum above 2π: a path may bend by up to the excess) and a boundary vertex.
  bool holds_no_bend(int v);
  // Faces the chords' walks entered since the last pass counted them (PathStats::walked_faces).
  int walked() const { return walked_; }
  // The vertices the last zipper flipped, in strip order.
  const std::vector<int>& zipper_pivots() const { return pivots_; }
  // Bytes held for the mesh (the vertex angle sums; the scratch of the longest path is not counted).
  size_t bytes() const { return angle_sums_.capacity() * sizeof(double); }

  // ---- Mutators: the steps ----
  // Phase (ii): takes `strip` with the end points `start` on its first face and `end` on its last,
  // lays it out and finds its funnel path; forgets the frozen vertices of the last path.
  void begin(const MeshPoint& start, const MeshPoint& end, const std::vector<int>& strip);
  // One pass of phase (iii): every reflex vertex not frozen, largest turn first, gets a flip (a
  // chord, a zipper or a semi-star) unless its faces touch an earlier one's; the flips are kept
  // together if they shorten the path, else the largest turn's alone if it does (the others'
  // zippers and chords are then given up: a semi-star at a reflex vertex shortens the path, they
  // need not). False when no reflex vertex was left (the path is locally shortest).
  bool pass(PathStats* stats = nullptr);
  // The semi-star flip of apex j, where the path turns by `turn` around vertex v = apices()[j].vertex
  // whose run in the strip is strip[first..last]: flip.other is v's other semi-star, from
  // strip[first] round to strip[last]. False when the path cannot be shortened at v (then the pass
  // freezes it): the other side is open (a boundary) or spans at least π, i.e. v's angle sum θ
  // satisfies θ − (π + turn) ≥ π.
  bool flip(size_t j, double turn, int first, int last, Flip& flip);
  // Widens the semi-star flip of apex j (made by `flip`) to a zipper: the strip's boundary vertices
  // next to v, on v's side and between the neighbouring apices, that would still block the path with
  // v out of the way (they lie on v's side of the line between the neighbouring apices) are flipped
  // with it. Leaves `flip` as it is when no such vertex exists, or v's zipper did not shorten the
  // path before. With `back` or `ahead` above 1 (a slide's), every boundary vertex on v's side from
  // v back to the last bend the slide passes (apex j-back+1) and ahead to apex j+ahead-1 is flipped:
  // not the ones the path does not touch between those and the bends where it stops, which block
  // nothing (flipped, they pushed the path round their far side: on the knotted tube of
  // BENCHMARKS.md a path 1% longer, and the bend moved a vertex a pass, 2026-12-08).
  void zipper(size_t j, Flip& flip, size_t back = 1, size_t ahead = 1, int lo = -1, int hi = -1);
  // The slide of apex j: how many apices back (the return value) and ahead the path leaves the
  // boundary vertices next to v once v is flipped. A path pressed against a row of saddle vertices
  // (each with angle sum 2π + e, e > 0) may turn by up to e at each of them and stay locally
  // shortest, so it follows such a row, bending at every vertex, and leaves it with a larger bend v.
  // Flipping v makes the vertex before it the bend (a little smaller), and so on: the bend slides
  // along the row a vertex per pass (BENCHMARKS.md, "Surface at scale", Slides). Here the
  // slide is worked out in the plane instead: going round a vertex of angle excess e on its other
  // side turns the layout beyond it by e about it, so where the vertices from v back to apex d are
  // passed on their other side, the far apex lies at the near one's position turned about each of
  // them in turn; d is passed too while the path would still bend at d by more than d's excess, in
  // v's direction (d frozen, on v's side, at most options.slide_gap untouched boundary vertices from
  // the last). Likewise ahead, from the apex the slide leaves. 1 and 1: no slide, also when it
  // would pass fewer than options.slide_min bends.
  size_t slide(size_t j, size_t& ahead);
  // The glide of apex j: a bend v (a saddle) against a row of saddle vertices the path does not
  // touch (between v and its neighbouring apices, on v's side). Flipping v makes the next of them the
  // bend, by that vertex's excess smaller, and so on: the bend glides along the row a vertex per pass
  // until it fades (BENCHMARKS.md, "Surface at scale", Spans and glides). Worked out in the plane as
  // the slide's: the portals lo (back towards apex j-1) and hi (ahead towards apex j+1) of the first
  // vertices where the path, the layout beyond each vertex passed turned about it by its excess,
  // would no longer bend by more than their excess (or that are not saddles); the side vertices
  // strictly between them are flipped with v (zipper). -1 for a side that passes none or runs into
  // the neighbouring apex; false when both are.
  bool glide(size_t j, int& lo, int& hi);
  // The chord flip of apex j: the faces along the straight line from apex j-1 (p) to apex j+1 (q),
  // followed across the mesh from p (aimed once more where the surface turned the line), then
  // around q to its strip faces. False (flip unusable) when the line meets a boundary or a vertex,
  // misses q twice, or cannot make the path shorter, or its faces are the strip's own (the walk met
  // q's faces early and went round q back to the strip: nothing would change, and such a chord took
  // its neighbours' faces pass after pass); `room` bounds the faces it may replace.
  bool chord(size_t j, const ChordRoom& room, Flip& flip);
  // The chord from apex jp to apex jq (jp < jq - 1, room from the faces around apex jp to those
  // around apex jq): the line across every bend between them at once, aimed again up to `aims`
  // times. False likewise, or when the line is not shorter than the path's way between them.
  bool chord(size_t jp, size_t jq, const ChordRoom& room, Flip& flip, int aims = 1);
  // `chord`, unless apex j's chord failed between the same neighbouring apices' vertices before.
  bool walk_chord(size_t j, const ChordRoom& room, Flip& flip);
  // The strip with `chosen` made (non-overlapping, in strip order) into `out`, and its layout into
  // `u`: the strip's own between the changes, each piece moved rigidly to where the change before it
  // leaves it; a chord's faces where its trace laid them (moved likewise); other faces laid anew.
  // `splice` tells the funnel where the strips agree (splice.path null when a loop had to be cut).
  void apply(const std::vector<const Flip*>& chosen, std::vector<int>& out, UnfoldedStrip& u, Splice& splice);
  // The trial path with `chosen` made (apply), and its length (shorten).
  double lay_trial(const std::vector<const Flip*>& chosen);
  // Makes the trial strip the strip if its path (`trial_length` long) is shorter.
  bool keep_trial(double trial_length);
  // A pass that straightens the windows around its reflex vertices (candidates_) to the end, each on its
  // own, and keeps their strips if the path gets shorter. False (nothing done) when the strip is
  // shorter than options.window_min_faces or the windows would cover more than half of it.
  bool windowed_pass(PathStats* stats);
  // The faces strip[first..last] between apices ja and jb (end points there) straightened to the
  // end on their own; `flip` replaces them by the result. False when the path there did not get
  // shorter.
  bool straighten_window(size_t ja, size_t jb, int first, int last, Flip& flip, PathStats* stats);
  // A pass of spans (pass() tries it on its reflex apices, candidates_): for each run of at least
  // options.span_min_bends consecutive ones at vertices that hold no bend (holds_no_bend), the
  // chord from the apex before the run to the one after it (chord(jp, jq)), all kept together if
  // they shorten the path. False (nothing kept) when there was none or they did not shorten it;
  // after options.span_failures such passes the path tries no more.
  bool span_pass(PathStats* stats);
  // The funnel path of an unfolded strip from the start to the end point (`raw`: as the funnel made
  // it; `out`: where it goes straight on dropped), and its length.
  double shorten(const UnfoldedStrip& u, std::vector<Apex>& raw, std::vector<Apex>& out, const Splice* splice) const;

 private:
  // Whether the path through v, turning by `turn`, is locally shortest there (by v's angle sum,
  // once known: false while it is NaN).
  bool straight_through(int v, double turn) const { return angle_sums_[v] - kPi - turn >= kPi - 1e-9; }
  // Whether the strip holds apex x's vertex on its left.
  bool on_left(const Apex& x) const;
  // Whether strip[first..last] touches the faces of this pass's flips so far.
  bool overlaps(int first, int last) const;
  // Makes `made` (flips_[used_]) one of this pass's flips: its faces are taken.
  void take(const Flip& made);
  // Frees the faces this pass's flips took, and counts the chords' walks into stats.
  void end_taking(PathStats* stats);
  // Whether v is frozen for a path turning by `turn` there: it was frozen at a turn at least as
  // large (a vertex where the path is locally shortest stays so while the turn does not grow).
  bool is_frozen(int v, double turn) const;
  // Freezes v up to `turn` (infinity: for good, a vertex that cannot be flipped).
  void freeze(int v, double turn, PathStats* stats);
  // The angle sum around v (cached in angle_sums_), NaN for a boundary vertex.
  double angle_sum(int v);
  // The vertex and layout position of portal i's end on the left (or right) side of the strip.
  int side_vertex(bool left, int i) const {
    return left ? path_.unfolded.portals[i].left_vertex : path_.unfolded.portals[i].right_vertex;
  }
  const Vec2& side_pos(bool left, int i) const { return left ? path_.unfolded.left(i) : path_.unfolded.right(i); }
  // Slides and glides: m followed by the turn about vertex x (laid at c) by its angle excess, the
  // way that opens a bend of a path turning to `side`'s sign (< 0: right); false for a boundary
  // vertex.
  bool turn_about(int x, const Vec2& c, double side, PlaneMotion& m);
  // Whether a path coming into vertex x along `in` and leaving along `out` bends there to `side`'s
  // sign by more than x's excess lets it (it is passed: flipped with the bend).
  bool bends_past(int x, double side, const Vec2& in, const Vec2& out);
  // Whether apex j's vertex is frozen for the path's turn there, told by the turn's cosine alone
  // (false: not told; `is_frozen` on the turn decides). Most apices of a long path are frozen, and
  // the pass then needs no atan2 for them.
  bool surely_frozen(size_t j) const;

  const TriMesh& mesh_;
  std::vector<int>& face_marks_;
  // Angle sum around each vertex, filled in when a flip first needs it (NaN until then).
  std::vector<double> angle_sums_;

  // The path: its end points (on the strip's first and last faces; flips keep those faces), the
  // strip, its unfolding, its funnel path (`made`: the funnel's own apices, before those where it
  // goes straight on are dropped) and that path's length.
  struct Path {
    MeshPoint start, end;
    std::vector<int> strip;
    UnfoldedStrip unfolded;
    std::vector<Apex> apices, made;
    double length = 0;
  };
  Path path_;
  bool laid_ = false;  // path_ is begin()'s, no pass since
  // The path being tried, likewise (its strip laid out from the path's by `apply`).
  Path trial_;
  Splice splice_;  // how the trial strip differs from the strip

  // Vertices frozen (with the largest turn they are frozen for), and those whose zipper / chord
  // did not shorten the path (they get the semi-star from then on).
  VertexSet frozen_, no_chain_, no_chord_;
  // Per vertex, the neighbouring apices' vertices (p·2^32 + q) between which its chord's walk last
  // failed.
  VertexSet failed_chords_;
  // Per frozen vertex, the cosine of the largest turn it is frozen for (with is_frozen's 1e-9), or
  // -2 when that is π or more (frozen for every turn).
  VertexSet frozen_cos_;
  // This pass's flips (the first used_ of flips_), its vertices by turn, and the flips tried.
  std::vector<Flip> flips_;
  size_t used_ = 0;
  std::vector<uint8_t> taken_;  // per strip index: 1 where this pass's flips so far change the strip
  std::vector<std::pair<double, size_t>> order_;
  std::vector<size_t> candidates_;  // order_'s apices in path order (windows and spans read them)
  std::vector<const Flip*> chosen_;
  // A zipper's vertices and faces; a chord's walk: the faces it entered, where it laid them, and
  // the edge it left each face by along the line.
  std::vector<int> pivots_, zipper_faces_, fan_;
  std::vector<int> walk_faces_;
  std::vector<std::array<Vec2, 3>> walk_laid_;
  std::vector<int8_t> walk_exits_;
  int walked_ = 0;  // faces the chords' walks entered since the last pass's count

  // Windows: the apices and faces of each (strip order), the flips that replace them, and the path
  // outside while one is straightened. in_window_: a window's passes are running (they do not open
  // windows of their own); windows_off_: the last windowed pass changed nothing, so the next pass
  // is a whole one.
  struct Window {
    size_t ja, jb;
    int first, last;
  };
  std::vector<Window> windows_;
  std::vector<Flip> window_flips_;
  Path outer_;
  bool in_window_ = false, windows_off_ = false;
  int span_failures_ = 0;  // span passes of this path that did not shorten it
};

}  // namespace splinekit::surface
