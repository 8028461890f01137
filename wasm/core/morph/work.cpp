#include "work.h"

#include <cmath>

#include "common/bezier.h"

namespace splinekit::morph {

std::string validate(const WorkOptions& o) {
  auto bad = [](double v) { return !std::isfinite(v) || v < 0; };
  if (bad(o.stretching)) return "the stretching coefficient c_s must be a finite number >= 0";
  if (bad(o.bending)) return "the bending coefficient c_b must be a finite number >= 0";
  if (bad(o.kinking)) return "the kinking coefficient c_k must be a finite number >= 0";
  if (!std::isfinite(o.kink_exponent) || o.kink_exponent <= 0)
    return "the kink exponent e_k must be a finite number > 0";
  return "";
}

double stretching_work(double l1, double l2, const WorkOptions& o) {
  const double s = l1 + l2;
  return s > 0 ? o.stretching * (l2 - l1) * (l2 - l1) / s : 0.0;
}

double bending_work(double alpha1, double alpha2, double l1, double l2, const WorkOptions& o) {
  const double s = l1 + l2;
  return s > 0 ? o.bending * (alpha2 - alpha1) * (alpha2 - alpha1) / s : 0.0;
}

double kinking_work(double theta1, double theta2, const WorkOptions& o) {
  const double d = std::abs(theta2 - theta1);
  if (d == 0) return 0.0;
  return o.kinking * (o.kink_exponent == 1.0 ? d : std::pow(d, o.kink_exponent));
}

double travel_work(double l1, double l2, const double* p, const double* q, const WorkOptions& o) {
  if (o.travel == 0) return 0.0;
  const double dx = p[0] - q[0], dy = p[1] - q[1];
  return o.travel * 0.5 * (l1 + l2) * (dx * dx + dy * dy);
}

double turn_angle(const Vec2& u, const Vec2& v) {
  if (u.squaredNorm() == 0 || v.squaredNorm() == 0) return 0.0;
  return std::atan2(cross(u, v), u.dot(v));
}

double segment_bending(const double* c, int samples) {
  double total = 0;
  Vec2 prev = Vec2::Zero();
  const double scale = std::abs(c[6] - c[0]) + std::abs(c[7] - c[1]) + std::abs(c[2] - c[0]) + std::abs(c[3] - c[1]) +
                       std::abs(c[4] - c[2]) + std::abs(c[5] - c[3]);
  const double tiny = 1e-12 * scale;
  // The end tangents are the limits of B'(t): the first distinct control point from each end.
  auto end_tangent = [&](int from, int step) -> Vec2 {
    const Vec2 p = vec2_at(c, from);
    for (int s = 1; s <= 3; ++s) {
      const Vec2 d = vec2_at(c, from + s * step) - p;
      if (d.norm() > tiny) return step > 0 ? d : Vec2(-d);
    }
    return Vec2::Zero();
  };
  for (int i = 0; i <= samples; ++i) {
    const Vec2 d = i == 0         ? end_tangent(0, 1)
                   : i == samples ? end_tangent(3, -1)
                                  : bezier_derivative(c, double(i) / samples, 1);
    if (d.norm() <= tiny) continue;
    if (prev.squaredNorm() > 0) total += turn_angle(prev, d);
    prev = d;
  }
  return total;
}

namespace {

// The tangent direction leaving point index p forwards along control points (first distinct one).
Vec2 direction(const KnotChain& c, int from, int step) {
  const int count = int(c.points.size() / 2);
  const Vec2 p = vec2_at(c.points.data(), from);
  for (int s = 1; s <= 3; ++s) {
    int q = from + s * step;
    if (c.closed) q = ((q % count) + count) % count;
    if (q < 0 || q >= count) break;
    const Vec2 d = vec2_at(c.points.data(), q) - p;
    if (d.squaredNorm() > 0) return step > 0 ? d : Vec2(-d);
  }
  return Vec2::Zero();
}

}  // namespace

ChainMeasure measure(const KnotChain& c, double reference_length, const Frame& frame) {
  ChainMeasure m;
  const int n = c.segments();
  m.length.resize(size_t(n));
  m.bending.resize(size_t(n));
  m.kink.assign(size_t(c.anchors()), 0.0);
  m.middle.resize(2 * size_t(n));
  m.anchor.resize(2 * size_t(c.anchors()));
  for (int a = 0; a < c.anchors(); ++a) {
    m.anchor[2 * size_t(a)] = (c.points[6 * size_t(a)] - frame.cx) / frame.radius;
    m.anchor[2 * size_t(a) + 1] = (c.points[6 * size_t(a) + 1] - frame.cy) / frame.radius;
  }
  double seg[8];
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 4; ++i) {
      const int p = c.point_index(k, i);
      seg[2 * i] = c.points[2 * size_t(p)];
      seg[2 * i + 1] = c.points[2 * size_t(p) + 1];
    }
    m.length[size_t(k)] = bezier_arc_length(seg, 0.0, 1.0, 1e-9 * reference_length) / reference_length;
    m.bending[size_t(k)] = segment_bending(seg);
    const Vec2 mid = bezier_point(seg, 0.5);
    m.middle[2 * size_t(k)] = (mid.x() - frame.cx) / frame.radius;
    m.middle[2 * size_t(k) + 1] = (mid.y() - frame.cy) / frame.radius;
  }
  for (int a = 0; a < c.anchors(); ++a) {
    if (c.smooth[size_t(a)]) continue;
    if (!c.closed && (a == 0 || a == n)) continue;
    m.kink[size_t(a)] = turn_angle(direction(c, 3 * a, -1), direction(c, 3 * a, +1));
  }
  return m;
}

}  // namespace splinekit::morph
