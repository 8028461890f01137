// splinekit — the work of bending and stretching one wire into another (Sederberg & Greenwood 1993, §5).
//
// A segment of wire has a length L and a total arc bending α (the signed turn of its tangent from
// start to end, ∫κ ds); an anchor has a kink θ (the signed turn of the tangent across a C0 join, 0
// at a smooth one). Blending a segment (L1, α1) into (L2, α2) and a kink θ1 into θ2 costs
//   stretching  W_s = c_s (L2 − L1)² / (L1 + L2)        (eq. 3)
//   bending     W_b = c_b (α2 − α1)² / (L1 + L2)        (eq. 4)
//   kinking     W_k = c_k |θ2 − θ1|^e_k                 (eq. 5)
// A segment blended from or into a point has L2 = α2 = 0 (or L1 = α1 = 0).
//
// Lengths are measured in units of a reference length (the mean size of the two drawings), so the
// work, and the least-work correspondence, do not change when both keys are moved, rotated or
// scaled together. W_s and W_b are invariant under rigid motions of either key; scaling one key
// changes only W_s (α and θ do not change under a scale).
#pragma once

#include <string>
#include <vector>

#include "chain.h"
#include "common/geometry.h"

namespace splinekit::morph {

// The work coefficients (§5). Defaults are the paper's: c_s = 1, c_b = 1, c_k = 4, e_k = 1; it
// reports the same good blends for 0.01 <= c_s <= 16 and 0.00001 <= e_k <= 10.
struct WorkOptions {
  double stretching = 1.0;     // c_s >= 0
  double bending = 1.0;        // c_b >= 0
  double kinking = 4.0;        // c_k >= 0
  double kink_exponent = 1.0;  // e_k > 0
  // Beyond the paper: c_t of the travel work W_t = c_t (L1 + L2)/2 |p̂1 − p̂2|², where p̂ is a
  // segment's midpoint (or the anchor it collapses to) in its drawing's normalized frame (centroid
  // at 0, RMS radius 1). Eq. 3–5 only see lengths and angles, so on outlines cut into many similar
  // segments a path can slide along the other contour almost for free; this keeps corresponding
  // points at corresponding places. Invariant when both keys move, rotate or scale together; 0
  // gives the paper's model (where a rotated copy costs nothing).
  double travel = 1.0;  // c_t >= 0
};

// Returns "" when every coefficient is finite and in range, else a message naming it.
std::string validate(const WorkOptions& options);

double stretching_work(double l1, double l2, const WorkOptions& o);
double bending_work(double alpha1, double alpha2, double l1, double l2, const WorkOptions& o);
double kinking_work(double theta1, double theta2, const WorkOptions& o);

// What the work terms read of a chain: per segment its length (in reference units) and bending α,
// per anchor its kink θ (0 at smooth anchors and at the ends of an open chain); for the travel
// work, segment midpoints and anchors in the drawing's normalized frame.
struct ChainMeasure {
  std::vector<double> length;   // n
  std::vector<double> bending;  // n, radians
  std::vector<double> kink;     // anchors, radians in (−π, π]
  std::vector<double> middle;   // 2n: normalized midpoint (x, y) of each segment (t = 1/2)
  std::vector<double> anchor;   // 2 * anchors: normalized anchor positions
};

// A drawing's normalized frame: p̂ = (p − center) / radius.
struct Frame {
  double cx = 0, cy = 0, radius = 1;
};

// Travel work of a segment (length l1, normalized midpoint p) against a point q of length l2.
double travel_work(double l1, double l2, const double* p, const double* q, const WorkOptions& o);

// Total signed turn of the tangent of one cubic segment (8 doubles), in radians: the angle swept
// by B'(t) over [0, 1], tracked through `samples` steps (a zero derivative at an end, as when a
// handle sits on its anchor, is skipped).
double segment_bending(const double* segment, int samples = 32);

// Signed angle in (−π, π] from direction u to direction v (0 when either is zero).
double turn_angle(const Vec2& u, const Vec2& v);

// Measures a chain; lengths are divided by `reference_length`, positions mapped by `frame`.
ChainMeasure measure(const KnotChain& chain, double reference_length, const Frame& frame = {});

}  // namespace splinekit::morph
