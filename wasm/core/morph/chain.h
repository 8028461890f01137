// splinekit — a contour as a cubic B-spline whose interior knots are double (C1) or triple (C0).
//
// Sederberg & Greenwood, "Shape blending of 2-D piecewise curves" (1993), §4: a chain of cubic
// Bézier segments becomes one cubic non-uniform B-spline. A junction whose handles are collinear
// gets a double knot, with the knot spacing chosen so the join is C1 (not merely G1): the ratio of
// the knot intervals on either side equals the ratio of the handle lengths. Any other junction
// gets a triple knot (C0). The C2 and C3 rows of the paper's table would lower the multiplicity
// further; glyph and drawing data is at most G1 at its joins, so they are not used (the Bézier
// control points of a double-knot B-spline are then its control points plus the anchors the
// double knots determine, which is what the blend interpolates, see blend.h).
//
// §6: segments longer than `max_length` (the paper: ~5% of the bounding box) are split by knot
// insertion; a split point is a C∞ join, kept as a double knot with intervals split in proportion.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace splinekit::morph {

struct KnotChain {
  bool closed = false;
  // Bézier control points, x,y pairs: 3n points closed (segment k ends at point 0 after the last),
  // 3n+1 open.
  std::vector<double> points;
  // Knot interval (parameter length) of each segment, n values; 0 for a segment collapsed to a point.
  std::vector<double> knots;
  // One flag per anchor (n closed, n+1 open; anchor a is point 3a): 1 when the anchor sits on a
  // double knot (a C1 join), 0 on a triple knot (C0) and at the ends of an open chain.
  std::vector<uint8_t> smooth;

  int segments() const { return int(knots.size()); }
  int anchors() const { return int(smooth.size()); }
  // Point index of control point c of segment k (wraps for closed chains).
  int point_index(int k, int c) const;
};

// Options of `chain_from_bezier`. Lengths are absolute (drawing units).
struct ChainOptions {
  // A junction counts as smooth (double knot) when both handles are longer than `length_tolerance`
  // and the anchor lies within `length_tolerance` of the line through them (the paper's TOL: "the
  // width of the reverse map of a pixel into world space"; callers tie it to the drawing's size).
  double length_tolerance = 1e-6;
  // Segments longer than this (arc length) are split (§6); <= 0 disables the limit.
  double max_length = 0.0;
};

// Builds the chain from a spline of flat control points (3n+1 open, 3n closed, n >= 1). Knot
// intervals are proportional to arc length at C0 joins and follow the handle-length ratio at C1
// joins; they sum to 1. A closed chain is rotated to start at a C0 anchor when it has one (so every
// double knot is consistent); with none, anchor 0 is smooth only if the ratios close up.
// Returns "" or a message naming the problem (too few points, zero length).
std::string chain_from_bezier(const double* points, int point_count, bool closed, const ChainOptions& options,
                              KnotChain& out);

// Splits every segment longer than max_length into equal-parameter pieces (knot insertion).
void limit_segment_length(KnotChain& chain, double max_length);

// The same curve traversed backwards (anchor a becomes anchor n - a mod n closed, n - a open).
KnotChain reversed(const KnotChain& chain);

// The same closed curve starting at anchor `first` (a no-op for open chains).
KnotChain rotated(const KnotChain& chain, int first);

// A chain of `segments` segments all collapsed to the point (x, y): the partner of a contour that
// grows from or shrinks to a point.
KnotChain point_chain(double x, double y, int segments, bool closed);

}  // namespace splinekit::morph
