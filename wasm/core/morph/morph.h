// splinekit — least-work shape blending of two drawings whose in-betweens stay cubic Bézier splines.
//
// Sederberg & Greenwood, "Shape blending of 2-D piecewise curves" (1993), on their polygon
// algorithm ("A physically based approach to 2-D shape blending", SIGGRAPH 1992). The steps, each
// its own header and test:
//   1. chain.h          every contour → a cubic B-spline with double (C1) and triple (C0) knots (§4),
//                       segments limited in length by knot insertion (§6);
//   2. pairing.h        contours of the two keys paired by area, position and nesting;
//   3. work.h           stretching, bending and kinking work (§5, eq. 3–5);
//   4. correspondence.h the least-work knot correspondence of each pair (§6);
//   5. blend.h          in-betweens by interpolating control points and knots (§2), linear or intrinsic.
// Precompute (`setup`) once; `evaluate(t)` afterwards allocates nothing.
#pragma once

#include <string>
#include <vector>

#include "blend.h"
#include "chain.h"
#include "common/spline_set.h"
#include "correspondence.h"
#include "pairing.h"
#include "work.h"

namespace splinekit::morph {

enum class Direction { kWinding = 0, kBoth = 1, kForward = 2 };

struct MorphOptions {
  WorkOptions work;             // §5 coefficients (paper's defaults)
  double segment_limit = 0.05;  // max segment arc length, fraction of the contour's width, perimeter/π (§6); 0: none
  double continuity_tolerance = 1e-3;  // C1 test (the paper's TOL) as a fraction of the drawing's size
  // Which directions of B's contours are searched. kWinding (default): a closed contour of B is
  // traversed in the direction whose winding is that of its partner in A, open paths both ways.
  // The work of §5 does not see orientation: a reversed match can cost less yet turns the blend
  // inside out on the way (Nimbus Mono G → Nimbus Roman G: 54.8 reversed, 80.1 forward, with in-
  // betweens that cross themselves). kBoth: the least work over both directions; kForward: as given.
  Direction direction = Direction::kWinding;
  // The unit of length of the work terms, as a fraction of the mean total length of the two keys'
  // contours. Stretching work grows with length and bending work shrinks with it, so the unit sets
  // their balance; 0.01 makes a drawing's outline 100 units long, the scale of the paper's
  // 64-point glyphs. Tied to the keys' length, so moving, rotating or scaling both keys changes nothing.
  double length_unit = 0.01;
};

// A pinned correspondence in document space: the point of A nearest (ax, ay) meets the point of B
// nearest (bx, by) (both snapped to an anchor of the prepared chains).
struct MorphPin {
  double ax = 0, ay = 0, bx = 0, by = 0;
};

// One output contour: which contours it blends and what the search found.
struct BlendedContour {
  int contour_a = -1;  // index of A's spline, or -1 when it grows from a point
  int contour_b = -1;  // index of B's spline, or -1 when it shrinks to a point
  double work = 0;     // least work of this pair
  int start = 0;       // B's anchor matched to A's anchor 0 (closed)
  bool reversed = false;
  int pins = 0;  // pins that hold this pair
};

class Morph {
 public:
  // ---- Precompute -------------------------------------------------------------------------------
  // Validates both sets (at least one spline each, finite, well formed) and the options, leaves
  // out contours of zero length (they draw nothing), pairs contours, finds each pair's least-work correspondence and
  // prepares the blends. Returns "" or a message naming the problem; on failure the previous morph is kept.
  std::string setup(const SplineSet& a, const SplineSet& b, const MorphOptions& options,
                    const std::vector<MorphPin>& pins);

  // ---- Queries ------------------------------------------------------------------------------------
  int contour_count() const { return int(blends_.size()); }
  const std::vector<BlendedContour>& contours() const { return info_; }
  // Output layout: contour c owns points [start[c], start[c] + count[c]); closed[c] != 0 if closed.
  const std::vector<int32_t>& starts() const { return start_; }
  const std::vector<int32_t>& counts() const { return count_; }
  const std::vector<int32_t>& closed() const { return closed_; }
  int point_count() const { return total_points_; }
  // Per output anchor (over all contours, in order): 1 when C1 in every in-between.
  const std::vector<uint8_t>& coupled() const { return coupled_; }
  double work() const { return work_; }
  const SearchCounters& counters() const { return search_.counters(); }
  const ContourBlend& blend(int c) const { return blends_[size_t(c)]; }

  // ---- Update (no allocation) ------------------------------------------------------------------------
  // Writes the in-between at t into out (2 * point_count() doubles).
  void evaluate(double t, Interpolation mode, double* out);

 private:
  CorrespondenceSearch search_;
  std::vector<ContourBlend> blends_;
  std::vector<BlendedContour> info_;
  std::vector<int32_t> start_, count_, closed_;
  std::vector<uint8_t> coupled_;
  int total_points_ = 0;
  double work_ = 0;
};

}  // namespace splinekit::morph
