// splinekit — the in-betweens of two chains that share one knot structure (Sederberg & Greenwood 1993, §2).
//
// A correspondence path (correspondence.h) lays the two chains side by side, segment for segment:
// a step that advances only one chain pairs its segment with a segment collapsed to the other
// chain's anchor (a knot inserted where one exists, knot interval 0). The B-spline control points
// of each key are then its Bézier handles plus the anchors on triple knots; an anchor on a double
// knot in both keys (a C1 join, with no collapsed segment next to it) is not a control point but
// follows from its handles and knot intervals:
//   P = (Δr H_in + Δl H_out) / (Δl + Δr)
// (inserting a third knot there, B-spline → Bézier). In-betweens interpolate the control points
// and the knot intervals, then recover the anchors this way, so a join that is C1 in both keys is
// C1 in every in-between: the Bézier kink of the paper's Fig. 3 cannot appear. The keys' joins are
// G1 only within a tolerance; the small offset of each such anchor from its formula is kept per
// key and interpolated, so t = 0 and t = 1 give the keys exactly.
//
// Interpolation of the control points:
//  - kLinear: straight lines (§2);
//  - kIntrinsic: edge lengths, turning angles and the first edge's direction of the control
//    polygon are interpolated, and a closed polygon is closed again by the least weighted change of
//    its edge lengths (Sederberg, Gao, Wang & Mu 1993); its centroid moves on a straight line. A
//    rotated copy blends through rotated copies instead of shrinking.
#pragma once

#include <vector>

#include "chain.h"
#include "correspondence.h"

namespace splinekit::morph {

enum class Interpolation { kLinear = 0, kIntrinsic = 1 };

class ContourBlend {
 public:
  // ---- Constructors -----------------------------------------------------------------------------
  // a: chain A as searched; b: chain B in the searched direction, rotated so the correspondence's
  // start is its anchor 0; moves: the path (every step once). Allocates all scratch.
  void build(const KnotChain& a, const KnotChain& b, const std::vector<Move>& moves);

  // ---- Queries ------------------------------------------------------------------------------------
  bool closed() const { return closed_; }
  int segments() const { return segments_; }
  // Control points of an in-between: 3K closed, 3K + 1 open.
  int point_count() const { return closed_ ? 3 * segments_ : 3 * segments_ + 1; }
  // The keys laid out on the shared knot structure (2 * point_count() doubles each).
  const std::vector<double>& key(int which) const { return which == 0 ? a_ : b_; }
  // Per anchor: 1 when it is C1 in every in-between (double knot in both keys).
  const std::vector<uint8_t>& coupled() const { return coupled_; }

  // ---- Update (no allocation) ------------------------------------------------------------------------
  // Writes the in-between at t (2 * point_count() doubles): t = 0 gives key A, t = 1 key B.
  void evaluate(double t, Interpolation mode, double* out);

 private:
  void linear(double t, double* out) const;
  void intrinsic(double t, double* out);
  void prepare_intrinsic();
  void anchors_from_knots(double t, double* out) const;

  bool closed_ = false;
  int segments_ = 0;
  bool collapsed_key_ = false;  // one key is a single point: intrinsic falls back to linear
  std::vector<double> a_, b_, da_, db_, corr_a_, corr_b_;
  std::vector<uint8_t> coupled_;
  // Intrinsic: the control polygon (point indices), per key its edge lengths, turns and first angle.
  std::vector<int> polygon_;
  std::vector<double> len_a_, len_b_, turn_a_, turn_b_, weight_;
  double angle_a_ = 0, angle_b_ = 0;
  double centroid_a_[2] = {0, 0}, centroid_b_[2] = {0, 0};
  std::vector<double> edges_;  // scratch: 2 per polygon edge
};

}  // namespace splinekit::morph
