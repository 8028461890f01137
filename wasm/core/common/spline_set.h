// splinekit — a set of splines in flat arrays, the unit every capability works on.
//
// points: 2 * total_points doubles (x,y); spline s owns points [start[s], start[s] + count[s]),
// closed[s] != 0 for a closed spline (count = 3n) and 0 for an open one (count = 3n + 1).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "continuity.h"

namespace splinekit {

struct SplineSet {
  std::vector<double> points;
  std::vector<int32_t> start;
  std::vector<int32_t> count;
  std::vector<int32_t> closed;

  int spline_count() const { return int(start.size()); }
  int point_count() const { return int(points.size() / 2); }
  const double* spline_points(int s) const { return points.data() + 2 * start[s]; }
};

// Checks shapes, index ranges, point counts (3n+1 / 3n) and finiteness. Returns an empty string
// when the set is valid, else a message naming the first problem.
std::string validate(const SplineSet& set);

// Total number of cubic segments and of junctions.
int total_segments(const SplineSet& set);
int total_junctions(const SplineSet& set);

// Per-spline bounds, 4 doubles each (xmin, ymin, xmax, ymax), into out (4 * spline_count).
void spline_set_bounds(const SplineSet& set, double* out);

// Classifies every junction of every spline, spline by spline, into out (total_junctions).
void spline_set_classify(const SplineSet& set, const ContinuityOptions& options, JunctionInfo* out);

// Samples each segment at `per_segment` (>= 2) parameters t = k/(per_segment-1); segments are
// written one after another, spline by spline (2 * per_segment * total_segments doubles).
void spline_set_sample(const SplineSet& set, int per_segment, double* out);

}  // namespace splinekit
