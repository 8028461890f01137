// splinekit — continuity of cubic Bézier splines at their junctions.
//
// A junction is an interior anchor of a spline: for an open spline of n segments the anchors
// 3(j+1), j = 0..n-2; for a closed spline every anchor 3j, j = 0..n-1. Its tag says which
// constraint the skinning fit (Liu, Jacobson & Gingold 2014, §4) preserves there.
#pragma once

namespace splinekit {

// The numbers cross to TS: src/spline/spline.ts CONTINUITY_KINDS lists the kinds in this order.
enum class Continuity : int {
  kNone = 0,   // a break: nothing is preserved (only set by the user, never detected)
  kC0 = 1,     // position only: a corner
  kC1 = 2,     // equal tangent vectors: H_out - P = P - H_in
  kG1 = 3,     // collinear tangents with a fixed length ratio: H_out - P = ratio (P - H_in)
  kAngle = 4,  // a corner whose angle is kept (only set by the user, detected corners are C0)
};

// Tolerances of the classifier. Lengths are absolute (drawing units): callers derive them from
// the drawing's size (see `continuity_options_for_size`).
struct ContinuityOptions {
  double length_tolerance = 1e-6;  // a handle shorter than this is degenerate (zero length)
  double angle_tolerance = 1e-2;   // |sin| of the angle between tangents that still counts as G1 (~0.57°)
  double ratio_tolerance = 1e-3;   // |ratio - 1| that still counts as C1 rather than G1
};

// Options scaled to a drawing whose bounding-box diagonal is `size`:
// length_tolerance = relative_tolerance * size.
ContinuityOptions continuity_options_for_size(double size, double relative_tolerance = 1e-6);

// The classification of one junction.
struct JunctionInfo {
  Continuity kind = Continuity::kC0;
  double ratio = 1.0;  // |H_out - P| / |P - H_in| (C1, G1); 0 when a handle is degenerate
  double angle = 0.0;  // signed turn (radians, in (-pi, pi]) from the incoming to the outgoing tangent
};

// Classifies the junction at anchor p with incoming handle h_in and outgoing handle h_out
// (each a pointer to x,y). in_far and out_far are the next control points further away on the
// incoming and outgoing segments (used for the tangent direction when a handle is degenerate;
// then the junction is C0: a G1 ratio is undefined).
JunctionInfo classify_junction(const double* in_far, const double* h_in, const double* p, const double* h_out,
                               const double* out_far, const ContinuityOptions& options);

// Number of junctions of a spline of `point_count` points.
int spline_junction_count(int point_count, bool closed);

// Classifies every junction of one spline, in junction order, into out[0..count).
void classify_spline(const double* points, int point_count, bool closed, const ContinuityOptions& options,
                     JunctionInfo* out);

}  // namespace splinekit
