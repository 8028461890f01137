#include "continuity.h"

#include <cmath>

#include "bezier.h"
#include "geometry.h"

namespace splinekit {

ContinuityOptions continuity_options_for_size(double size, double relative_tolerance) {
  ContinuityOptions o;
  const double s = std::isfinite(size) && size > 0 ? size : 1.0;
  o.length_tolerance = relative_tolerance * s;
  return o;
}

JunctionInfo classify_junction(const double* in_far, const double* h_in, const double* p, const double* h_out,
                               const double* out_far, const ContinuityOptions& options) {
  const Vec2 P = vec2_at(p);
  const Vec2 a = P - vec2_at(h_in), b = vec2_at(h_out) - P;  // tangent vectors in and out
  const double eps = options.length_tolerance;
  const bool a_ok = a.norm() > eps, b_ok = b.norm() > eps;

  // Tangent directions: the handle, or the next distinct control point when it is degenerate.
  Vec2 da = a, db = b;
  if (!a_ok) da = P - vec2_at(in_far);
  if (!b_ok) db = vec2_at(out_far) - P;

  JunctionInfo info;
  info.kind = Continuity::kC0;
  info.ratio = (a_ok && b_ok) ? b.norm() / a.norm() : 0.0;
  const double la = da.norm(), lb = db.norm();
  if (la <= eps || lb <= eps) {
    info.angle = 0.0;  // a degenerate segment has no direction to compare
    return info;
  }
  const double sine = cross(da, db), dot = da.dot(db);  // |da| |db| sin and cos of the turn
  info.angle = std::atan2(sine, dot);
  if (!(a_ok && b_ok)) return info;

  const bool collinear = dot > 0 && std::abs(sine) <= options.angle_tolerance * la * lb;
  if (!collinear) return info;
  const double length_gap = std::abs(lb - la);
  const bool equal = length_gap <= eps || std::abs(info.ratio - 1.0) <= options.ratio_tolerance;
  info.kind = equal ? Continuity::kC1 : Continuity::kG1;
  return info;
}

int spline_junction_count(int point_count, bool closed) {
  const int n = spline_segment_count(point_count, closed);
  if (n == 0) return 0;
  return closed ? n : n - 1;
}

void classify_spline(const double* points, int point_count, bool closed, const ContinuityOptions& options,
                     JunctionInfo* out) {
  const int count = spline_junction_count(point_count, closed);
  auto pt = [&](int i) {
    i %= point_count;
    if (i < 0) i += point_count;
    return points + 2 * i;
  };
  for (int j = 0; j < count; ++j) {
    const int anchor = closed ? 3 * j : 3 * (j + 1);
    out[j] = classify_junction(pt(anchor - 2), pt(anchor - 1), pt(anchor), pt(anchor + 1), pt(anchor + 2), options);
  }
}

}  // namespace splinekit
