#include "bezier.h"

#include <algorithm>
#include <cmath>

namespace splinekit {

namespace {

constexpr double kBinom3[4] = {1, 3, 3, 1};
constexpr double kBinom6[7] = {1, 6, 15, 20, 15, 6, 1};

// Roots of a t^2 + b t + c in the open interval (0,1), appended to roots; returns the count.
int quadratic_roots_01(double a, double b, double c, double* roots) {
  int n = 0;
  auto keep = [&](double t) {
    if (t > 0.0 && t < 1.0) roots[n++] = t;
  };
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (scale == 0.0) return 0;
  if (std::abs(a) <= 1e-12 * scale) {
    if (b != 0.0) keep(-c / b);
    return n;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  // Numerically stable pair: q = -(b + sign(b) sqrt(disc)) / 2.
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  keep(q / a);
  if (q != 0.0) keep(c / q);
  return n;
}

// 7-point Gauss–Legendre on [a,b] of |B'(t)|.
double gauss_speed(const double* c, double a, double b) {
  static const double x[7] = {0.0,
                              0.4058451513773971669066064,
                              -0.4058451513773971669066064,
                              0.7415311855993944398638648,
                              -0.7415311855993944398638648,
                              0.9491079123427585245261897,
                              -0.9491079123427585245261897};
  static const double w[7] = {0.4179591836734693877551020, 0.3818300505051189449503698, 0.3818300505051189449503698,
                              0.2797053914892766679014678, 0.2797053914892766679014678, 0.1294849661688696932706114,
                              0.1294849661688696932706114};
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double sum = 0;
  for (int i = 0; i < 7; ++i) sum += w[i] * bezier_derivative(c, mid + half * x[i], 1).norm();
  return sum * half;
}

double adaptive_length(const double* c, double a, double b, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double left = gauss_speed(c, a, m), right = gauss_speed(c, m, b);
  if (depth >= 24 || std::abs(left + right - whole) <= tol) return left + right;
  return adaptive_length(c, a, m, left, 0.5 * tol, depth + 1) + adaptive_length(c, m, b, right, 0.5 * tol, depth + 1);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Bernstein basis
// ---------------------------------------------------------------------------------------------

Eigen::Vector4d bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
}

Eigen::Matrix4d bernstein_gram() {
  Eigen::Matrix4d g;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g(i, j) = kBinom3[i] * kBinom3[j] / (7.0 * kBinom6[i + j]);
  return g;
}

// ---------------------------------------------------------------------------------------------
// One cubic segment
// ---------------------------------------------------------------------------------------------

Vec2 bezier_point(const double* c, double t) {
  const Eigen::Vector4d b = bernstein(t);
  return b[0] * vec2_at(c, 0) + b[1] * vec2_at(c, 1) + b[2] * vec2_at(c, 2) + b[3] * vec2_at(c, 3);
}

Vec2 bezier_derivative(const double* c, double t, int order) {
  const double s = 1.0 - t;
  const Vec2 p0 = vec2_at(c, 0), p1 = vec2_at(c, 1), p2 = vec2_at(c, 2), p3 = vec2_at(c, 3);
  switch (order) {
    case 0:
      return bezier_point(c, t);
    case 1:
      return 3 * (s * s * (p1 - p0) + 2 * s * t * (p2 - p1) + t * t * (p3 - p2));
    case 2:
      return 6 * (s * (p2 - 2 * p1 + p0) + t * (p3 - 2 * p2 + p1));
    case 3:
      return 6 * (p3 - 3 * p2 + 3 * p1 - p0);
    default:
      return Vec2::Zero();
  }
}

void bezier_split(const double* c, double t, double* left, double* right) {
  const Vec2 p0 = vec2_at(c, 0), p1 = vec2_at(c, 1), p2 = vec2_at(c, 2), p3 = vec2_at(c, 3);
  const Vec2 a = p0 + t * (p1 - p0), b = p1 + t * (p2 - p1), d = p2 + t * (p3 - p2);
  const Vec2 e = a + t * (b - a), f = b + t * (d - b);
  const Vec2 m = e + t * (f - e);
  const Vec2 l[4] = {p0, a, e, m}, r[4] = {m, f, d, p3};
  for (int i = 0; i < 4; ++i) {
    if (left) left[2 * i] = l[i].x(), left[2 * i + 1] = l[i].y();
    if (right) right[2 * i] = r[i].x(), right[2 * i + 1] = r[i].y();
  }
}

double bezier_arc_length(const double* c, double t0, double t1, double tol) {
  if (t0 == t1) return 0.0;
  const double sign = t1 < t0 ? -1.0 : 1.0;
  if (t1 < t0) std::swap(t0, t1);
  return sign * adaptive_length(c, t0, t1, gauss_speed(c, t0, t1), std::max(tol, 1e-15), 0);
}

void bezier_bounds(const double* c, double* out) {
  out[0] = std::min(c[0], c[6]);
  out[1] = std::min(c[1], c[7]);
  out[2] = std::max(c[0], c[6]);
  out[3] = std::max(c[1], c[7]);
  for (int axis = 0; axis < 2; ++axis) {
    const double p0 = c[axis], p1 = c[2 + axis], p2 = c[4 + axis], p3 = c[6 + axis];
    // B'(t)/3 = (1-t)^2 (p1-p0) + 2t(1-t)(p2-p1) + t^2 (p3-p2) as a t^2 + b t + c.
    const double d0 = p1 - p0, d1 = p2 - p1, d2 = p3 - p2;
    double roots[2];
    const int n = quadratic_roots_01(d0 - 2 * d1 + d2, 2 * (d1 - d0), d0, roots);
    for (int k = 0; k < n; ++k) {
      const double v = bezier_point(c, roots[k])[axis];
      out[axis] = std::min(out[axis], v);
      out[2 + axis] = std::max(out[2 + axis], v);
    }
  }
}

void bezier_sample(const double* c, int samples, double* out) {
  for (int k = 0; k < samples; ++k) {
    const Vec2 p = bezier_point(c, samples > 1 ? double(k) / (samples - 1) : 0.0);
    out[2 * k] = p.x();
    out[2 * k + 1] = p.y();
  }
}

// ---------------------------------------------------------------------------------------------
// Splines
// ---------------------------------------------------------------------------------------------

int spline_segment_count(int point_count, bool closed) {
  if (point_count <= 1) return 0;
  return closed ? point_count / 3 : (point_count - 1) / 3;
}

void spline_segment(const double* points, int point_count, bool closed, int s, double* seg) {
  for (int k = 0; k < 4; ++k) {
    int i = 3 * s + k;
    if (closed && i >= point_count) i -= point_count;
    seg[2 * k] = points[2 * i];
    seg[2 * k + 1] = points[2 * i + 1];
  }
}

void spline_bounds(const double* points, int point_count, bool closed, double* out) {
  out[0] = out[1] = INFINITY;
  out[2] = out[3] = -INFINITY;
  const int segments = spline_segment_count(point_count, closed);
  if (segments == 0) {
    for (int i = 0; i < point_count; ++i) {
      out[0] = std::min(out[0], points[2 * i]);
      out[1] = std::min(out[1], points[2 * i + 1]);
      out[2] = std::max(out[2], points[2 * i]);
      out[3] = std::max(out[3], points[2 * i + 1]);
    }
    return;
  }
  double seg[8], b[4];
  for (int s = 0; s < segments; ++s) {
    spline_segment(points, point_count, closed, s, seg);
    bezier_bounds(seg, b);
    out[0] = std::min(out[0], b[0]);
    out[1] = std::min(out[1], b[1]);
    out[2] = std::max(out[2], b[2]);
    out[3] = std::max(out[3], b[3]);
  }
}

}  // namespace splinekit
