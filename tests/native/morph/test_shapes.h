// Shapes the morph tests share: closed and open Bézier chains with known geometry.
#pragma once

#include <cmath>
#include <vector>

#include "common/geometry.h"
#include "common/spline_set.h"

namespace splinekit::morph::test {

// A closed circle of radius r about (cx, cy) from `n` C1 arcs (counter-clockwise, y up).
inline std::vector<double> circle(double cx, double cy, double r, int n = 4) {
  std::vector<double> p;
  const double h = 4.0 / 3.0 * std::tan(kPi / (2 * n)) * r;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n, b = 2 * kPi * (k + 1) / n;
    p.insert(p.end(), {cx + r * std::cos(a), cy + r * std::sin(a), cx + r * std::cos(a) - h * std::sin(a),
                       cy + r * std::sin(a) + h * std::cos(a), cx + r * std::cos(b) + h * std::sin(b),
                       cy + r * std::sin(b) - h * std::cos(b)});
  }
  return p;
}

// A closed polygon as a chain of straight cubic segments (handles at thirds): C0 corners.
inline std::vector<double> polygon(const std::vector<Vec2>& v) {
  std::vector<double> p;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec2 a = v[i], b = v[(i + 1) % v.size()];
    const Vec2 h1 = a + (b - a) / 3.0, h2 = a + 2.0 * (b - a) / 3.0;
    p.insert(p.end(), {a.x(), a.y(), h1.x(), h1.y(), h2.x(), h2.y()});
  }
  return p;
}

// A closed shape with smooth (C1) and corner joins: a "D" — a half circle closed by a line.
inline std::vector<double> d_shape(double s = 1.0) {
  // Right half circle from (0,-1) through (1,0) to (0,1): two arcs (C1 at (1,0)); line back down.
  const double h = 4.0 / 3.0 * std::tan(kPi / 8) * s;
  return {0, -s, h, -s, s, -h, s, 0, s, h, h, s, 0, s, 0, s / 3, 0, -s / 3};
}

inline SplineSet set_of(const std::vector<std::vector<double>>& splines, const std::vector<bool>& closed) {
  SplineSet s;
  for (size_t i = 0; i < splines.size(); ++i) {
    s.start.push_back(int32_t(s.points.size() / 2));
    s.count.push_back(int32_t(splines[i].size() / 2));
    s.closed.push_back(closed[i] ? 1 : 0);
    s.points.insert(s.points.end(), splines[i].begin(), splines[i].end());
  }
  return s;
}

// Applies x' = a x + c y + e, y' = b x + d y + f to flat points.
inline std::vector<double> transformed(std::vector<double> p, double a, double b, double c, double d, double e,
                                       double f) {
  for (size_t i = 0; i < p.size(); i += 2) {
    const double x = p[i], y = p[i + 1];
    p[i] = a * x + c * y + e;
    p[i + 1] = b * x + d * y + f;
  }
  return p;
}

// Reverses a closed chain (point i → (3n − i) mod 3n) or an open one.
inline std::vector<double> reversed_points(const std::vector<double>& p, bool closed) {
  const size_t count = p.size() / 2;
  std::vector<double> out(p.size());
  for (size_t i = 0; i < count; ++i) {
    const size_t j = closed ? (count - i) % count : count - 1 - i;
    out[2 * j] = p[2 * i];
    out[2 * j + 1] = p[2 * i + 1];
  }
  return out;
}

}  // namespace splinekit::morph::test
