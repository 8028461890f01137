#include "spline_set.h"

#include <cmath>

#include "bezier.h"

namespace splinekit {

std::string validate(const SplineSet& set) {
  if (set.points.size() % 2 != 0)
    return "points must hold x,y pairs (odd length " + std::to_string(set.points.size()) + ")";
  const size_t n = set.start.size();
  if (set.count.size() != n || set.closed.size() != n) return "start, count and closed must have one entry per spline";
  const int total = set.point_count();
  for (size_t s = 0; s < n; ++s) {
    const int b = set.start[s], c = set.count[s];
    if (b < 0 || c < 1 || b + c > total)
      return "spline " + std::to_string(s) + " indexes points [" + std::to_string(b) + ", " + std::to_string(b + c) +
             ") outside the " + std::to_string(total) + " points";
    if (set.closed[s] ? (c % 3 != 0) : (c % 3 != 1))
      return "spline " + std::to_string(s) + " has " + std::to_string(c) +
             " points: " + (set.closed[s] ? "a closed spline needs 3n" : "an open spline needs 3n+1");
  }
  for (size_t i = 0; i < set.points.size(); ++i)
    if (!std::isfinite(set.points[i])) return "point " + std::to_string(i / 2) + " has a non-finite coordinate";
  return {};
}

int total_segments(const SplineSet& set) {
  int n = 0;
  for (int s = 0; s < set.spline_count(); ++s) n += spline_segment_count(set.count[s], set.closed[s] != 0);
  return n;
}

int total_junctions(const SplineSet& set) {
  int n = 0;
  for (int s = 0; s < set.spline_count(); ++s) n += spline_junction_count(set.count[s], set.closed[s] != 0);
  return n;
}

void spline_set_bounds(const SplineSet& set, double* out) {
  for (int s = 0; s < set.spline_count(); ++s)
    spline_bounds(set.spline_points(s), set.count[s], set.closed[s] != 0, out + 4 * s);
}

void spline_set_classify(const SplineSet& set, const ContinuityOptions& options, JunctionInfo* out) {
  for (int s = 0; s < set.spline_count(); ++s) {
    classify_spline(set.spline_points(s), set.count[s], set.closed[s] != 0, options, out);
    out += spline_junction_count(set.count[s], set.closed[s] != 0);
  }
}

void spline_set_sample(const SplineSet& set, int per_segment, double* out) {
  double seg[8];
  for (int s = 0; s < set.spline_count(); ++s) {
    const bool closed = set.closed[s] != 0;
    const int segments = spline_segment_count(set.count[s], closed);
    for (int k = 0; k < segments; ++k) {
      spline_segment(set.spline_points(s), set.count[s], closed, k, seg);
      bezier_sample(seg, per_segment, out);
      out += 2 * per_segment;
    }
  }
}

}  // namespace splinekit
