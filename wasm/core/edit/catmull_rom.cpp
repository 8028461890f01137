#include "edit/catmull_rom.h"

#include <algorithm>
#include <cmath>

#include "common/bezier.h"

namespace splinekit::edit {

double knot_exponent(Parameterization p) {
  switch (p) {
    case Parameterization::kUniform:
      return 0.0;
    case Parameterization::kChordal:
      return 1.0;
    case Parameterization::kCentripetal:
    default:
      return 0.5;
  }
}

std::string CatmullRom::set(const double* xy, int count, bool closed, Parameterization p) {
  const int minimum = closed ? 3 : 2;
  if (count < minimum) {
    return std::string("a ") + (closed ? "closed" : "open") + " Catmull-Rom curve needs at least " +
           std::to_string(minimum) + " control points, got " + std::to_string(count < 0 ? 0 : count);
  }
  if (int(p) < 0 || int(p) > 2)
    return "parameterization " + std::to_string(int(p)) + " is not uniform, centripetal or chordal";
  for (int i = 0; i < 2 * count; ++i) {
    if (!std::isfinite(xy[i])) {
      return "control point " + std::to_string(i / 2) + " has a non-finite " + (i % 2 ? "y" : "x") + " coordinate";
    }
    if (std::abs(xy[i]) > kMaxCoordinate) {
      return "control point " + std::to_string(i / 2) + " has an " + (i % 2 ? "y" : "x") +
             " coordinate beyond ±1e150 (squared lengths would overflow)";
    }
  }
  count_ = count;
  closed_ = closed;
  param_ = p;
  points_.assign(xy, xy + 2 * size_t(count));
  m_.assign(2 * size_t(count), 0.0);
  override_.assign(2 * size_t(count), 0.0);
  has_override_.assign(size_t(count), 0);
  dt_.assign(size_t(segment_count()), 1.0);
  rebuild();
  return "";
}

void CatmullRom::set_points(const double* xy) {
  std::copy(xy, xy + 2 * size_t(count_), points_.begin());
  rebuild();
}

void CatmullRom::set_tangent(int i, const Vec2& t) {
  const size_t k = size_t(wrap(i));
  override_[2 * k] = t.x();
  override_[2 * k + 1] = t.y();
  has_override_[k] = 1;
  rebuild();
}

void CatmullRom::clear_tangent(int i) {
  has_override_[size_t(wrap(i))] = 0;
  rebuild();
}

void CatmullRom::clear_tangents() {
  std::fill(has_override_.begin(), has_override_.end(), 0);
  rebuild();
}

double CatmullRom::interval(int i) const {
  const int segments = segment_count();
  if (closed_) return dt_[size_t(((i % segments) + segments) % segments)];
  return dt_[size_t(std::clamp(i, 0, segments - 1))];
}

void CatmullRom::rebuild() {
  double lo[2] = {points_[0], points_[1]}, hi[2] = {points_[0], points_[1]};
  for (int i = 1; i < count_; ++i) {
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::min(lo[a], points_[2 * size_t(i) + a]);
      hi[a] = std::max(hi[a], points_[2 * size_t(i) + a]);
    }
  }
  size_ = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  const double a = knot_exponent(param_);
  // A zero interval (coincident neighbours) would divide by zero in the pyramid; a floor far
  // below the drawing's resolution keeps every formula finite and the segment a point.
  const double floor = std::max(1e-12 * std::pow(size_, a), 1e-300);
  for (int s = 0; s < segment_count(); ++s) {
    const double chord = (control_point(s + 1) - control_point(s)).norm();
    dt_[size_t(s)] = a == 0.0 ? 1.0 : std::max(std::pow(chord, a), floor);
  }
  for (int i = 0; i < count_; ++i) {
    const double d0 = interval(i - 1), d1 = interval(i);
    Vec2 m;
    if (has_override_[size_t(i)]) {
      m = vec2_at(override_.data(), i) * (2.0 / (d0 + d1));
    } else {
      // Open ends repeat their point: control_point clamps the index.
      const Vec2 prev = control_point(i - 1), p = control_point(i), next = control_point(i + 1);
      m = (p - prev) / d0 - (next - prev) / (d0 + d1) + (next - p) / d1;
    }
    m_[2 * size_t(i)] = m.x();
    m_[2 * size_t(i) + 1] = m.y();
  }
}

Vec2 CatmullRom::point(int s, double u) const {
  if (tangent_overridden(s) || tangent_overridden(s + 1)) {
    double seg[8];
    segment_bezier(s, seg);
    return bezier_point(seg, u);
  }
  const Vec2 p0 = control_point(s - 1), p1 = control_point(s), p2 = control_point(s + 1), p3 = control_point(s + 2);
  const double d = interval(s);
  const double t0 = -interval(s - 1), t1 = 0.0, t2 = d, t3 = d + interval(s + 1), t = u * d;
  const Vec2 a1 = ((t1 - t) * p0 + (t - t0) * p1) / (t1 - t0);
  const Vec2 a2 = ((t2 - t) * p1 + (t - t1) * p2) / (t2 - t1);
  const Vec2 a3 = ((t3 - t) * p2 + (t - t2) * p3) / (t3 - t2);
  const Vec2 b1 = ((t2 - t) * a1 + (t - t0) * a2) / (t2 - t0);
  const Vec2 b2 = ((t3 - t) * a2 + (t - t1) * a3) / (t3 - t1);
  return ((t2 - t) * b1 + (t - t1) * b2) / (t2 - t1);
}

void CatmullRom::segment_bezier(int s, double* out) const {
  const int i = wrap(s), j = wrap(s + 1);
  const double d = interval(s) / 3.0;
  const Vec2 p = vec2_at(points_.data(), i), q = vec2_at(points_.data(), j);
  const Vec2 h0 = p + d * vec2_at(m_.data(), i), h1 = q - d * vec2_at(m_.data(), j);
  const Vec2 c[4] = {p, h0, h1, q};
  for (int k = 0; k < 4; ++k) {
    out[2 * k] = c[k].x();
    out[2 * k + 1] = c[k].y();
  }
}

Vec2 CatmullRom::derivative(int s, double u, int order) const {
  double seg[8];
  segment_bezier(s, seg);
  return bezier_derivative(seg, u, order);
}

Vec2 CatmullRom::unit_tangent(int s, double u) const {
  double seg[8];
  segment_bezier(s, seg);
  const double tiny = 1e-14 * std::max(size_, 1e-300);
  for (int order = 1; order <= 3; ++order) {
    Vec2 d = bezier_derivative(seg, u, order);
    // Where the velocity vanishes the curve leaves along +B'' (and arrives along -B'').
    if (order == 2 && u >= 0.5) d = -d;
    if (d.norm() > tiny) return d.normalized();
  }
  return {1.0, 0.0};
}

Vec2 CatmullRom::unit_normal(int s, double u) const {
  const Vec2 t = unit_tangent(s, u);
  return {-t.y(), t.x()};
}

Vec2 CatmullRom::tangent(int i) const {
  const int k = wrap(i);
  if (has_override_[size_t(k)]) return vec2_at(override_.data(), k);
  return vec2_at(m_.data(), k) * (0.5 * (interval(k - 1) + interval(k)));
}

Vec2 CatmullRom::normal_at(int i) const {
  const double tiny = 1e-14 * std::max(size_, 1e-300);
  Vec2 t = tangent(i);
  if (t.norm() <= tiny) t = control_point(i + 1) - control_point(i - 1);
  if (t.norm() <= tiny) return {0.0, 1.0};
  t.normalize();
  return {-t.y(), t.x()};
}

double CatmullRom::segment_length(int s) const {
  double seg[8];
  segment_bezier(s, seg);
  return bezier_arc_length(seg, 0.0, 1.0, 1e-10 * std::max(size_, 1e-300));
}

void CatmullRom::bezier(std::vector<double>& out_points, std::vector<JunctionInfo>& out_tags) const {
  const int segments = segment_count();
  const int n = closed_ ? 3 * segments : 3 * segments + 1;
  out_points.resize(2 * size_t(n));
  double seg[8];
  for (int s = 0; s < segments; ++s) {
    segment_bezier(s, seg);
    const int last = (s == segments - 1 && !closed_) ? 4 : 3;
    for (int k = 0; k < last; ++k) {
      out_points[2 * size_t(3 * s + k)] = seg[2 * k];
      out_points[2 * size_t(3 * s + k) + 1] = seg[2 * k + 1];
    }
  }
  const int junctions = closed_ ? count_ : count_ - 2;
  out_tags.resize(size_t(std::max(junctions, 0)));
  const double tiny = 1e-14 * std::max(size_, 1e-300);
  for (int j = 0; j < junctions; ++j) {
    const int i = closed_ ? j : j + 1;
    const double d0 = interval(i - 1), d1 = interval(i);
    JunctionInfo& tag = out_tags[size_t(j)];
    tag.angle = 0.0;
    if (vec2_at(m_.data(), i).norm() * std::min(d0, d1) <= tiny) {
      tag.kind = Continuity::kC0;
      tag.ratio = 0.0;
      continue;
    }
    tag.ratio = d1 / d0;
    tag.kind = std::abs(tag.ratio - 1.0) <= 1e-9 ? Continuity::kC1 : Continuity::kG1;
  }
}

}  // namespace splinekit::edit
