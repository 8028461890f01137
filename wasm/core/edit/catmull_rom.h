// splinekit — Catmull-Rom splines (Eyiyurekli & Breen, "Localized editing of Catmull-Rom
// splines", §3; Catmull & Rom 1974; the α-parameterisations of Yuksel, Schaefer & Keyser 2011).
//
// A Catmull-Rom spline interpolates its control points P_0..P_{n-1}: segment i runs from P_i to
// P_{i+1} (to P_0 after P_{n-1} when closed) and is shaped by P_{i-1} and P_{i+2}. An open curve
// repeats its end points (the paper's "first and last control points are inserted multiple
// times"), so it starts at P_0 and ends at P_{n-1}.
//
// Knots: the interval of segment i is dt_i = |P_{i+1} - P_i|^a with a = 0 (uniform), 1/2
// (centripetal: no cusp or self-intersection within a segment) or 1 (chordal). A repeated end
// point would give a zero interval; it takes its neighbour's interval instead, so the end tangent
// is (P_1 - P_0) / 2 per unit interval in every parameterisation, as in the uniform case.
//
// Two independent evaluations: `point` runs the Barry–Goldman pyramid on the knots, `bezier`
// writes the exact cubic Bézier form from the Hermite tangents
//   m_i = (P_i - P_{i-1}) / dt_{i-1} - (P_{i+1} - P_{i-1}) / (dt_{i-1} + dt_i) + (P_{i+1} - P_i) / dt_i
// (the derivative of the pyramid at knot i), with handles P_i ± m_i dt / 3. Tests hold them equal.
#pragma once

#include <string>
#include <vector>

#include "common/continuity.h"
#include "common/geometry.h"

namespace splinekit::edit {

// The knot spacing. The numbers cross to TS (src/edit/catmull-rom.ts PARAMETERIZATIONS).
enum class Parameterization : int { kUniform = 0, kCentripetal = 1, kChordal = 2 };

// Coordinates beyond this are refused: squared lengths of larger ones overflow a double.
inline constexpr double kMaxCoordinate = 1e150;

// The exponent a of dt = |ΔP|^a: 0, 0.5 or 1.
double knot_exponent(Parameterization p);

class CatmullRom {
 public:
  // ---- Constructors ---------------------------------------------------------------------------
  // Sets the control points (xy: 2·count doubles, x,y pairs) and rebuilds. Returns "" or a message
  // naming the problem (fewer than 2 points open / 3 closed, a non-finite coordinate or one beyond
  // ±kMaxCoordinate); on error the
  // previous curve is kept.
  std::string set(const double* xy, int count, bool closed, Parameterization p = Parameterization::kCentripetal);

  // ---- Mutators -------------------------------------------------------------------------------
  // Overwrites the coordinates (same count) and rebuilds; no allocation. xy: 2·count doubles.
  void set_points(const double* xy);
  // Overrides the tangent at control point i with T (position units; see `tangent`) and rebuilds.
  void set_tangent(int i, const Vec2& t);
  // Back to the Catmull-Rom tangent at i.
  void clear_tangent(int i);
  void clear_tangents();

  // ---- Queries --------------------------------------------------------------------------------
  int count() const { return count_; }
  bool closed() const { return closed_; }
  Parameterization parameterization() const { return param_; }
  int segment_count() const { return closed_ ? count_ : count_ - 1; }
  // 2·count doubles, x,y pairs.
  const std::vector<double>& points() const { return points_; }
  Vec2 control_point(int i) const { return vec2_at(points_.data(), wrap(i)); }
  // Knot interval of segment i (i may be -1 or segment_count() on an open curve: the repeated ends).
  double interval(int i) const;
  // Point of segment s at local parameter u in [0, 1] by the Barry–Goldman pyramid.
  Vec2 point(int s, double u) const;
  // The exact cubic Bézier of segment s: 8 doubles (x0 y0 x1 y1 x2 y2 x3 y3).
  void segment_bezier(int s, double* out) const;
  // Derivative d/du (order 1..3) of segment s at u, from its Bézier form.
  Vec2 derivative(int s, double u, int order = 1) const;
  // Unit tangent and left normal (tangent turned +90°) of segment s at u. Where the derivative
  // vanishes the next non-zero derivative gives the direction; a lone point gives (1,0) / (0,1).
  Vec2 unit_tangent(int s, double u) const;
  Vec2 unit_normal(int s, double u) const;
  // Tangent at control point i in position units: m_i (dt_{i-1} + dt_i) / 2, which is the classic
  // (P_{i+1} - P_{i-1}) / 2 for a uniform curve; or the override set by `set_tangent`.
  Vec2 tangent(int i) const;
  bool tangent_overridden(int i) const { return has_override_[size_t(wrap(i))] != 0; }
  // Unit left normal at control point i (from `tangent`; the chord P_{i+1} - P_{i-1} when it vanishes).
  Vec2 normal_at(int i) const;
  // Arc length of segment s (adaptive quadrature of its Bézier form, tolerance relative to size).
  double segment_length(int s) const;
  // Diagonal of the control points' bounding box (0 for a lone point).
  double size() const { return size_; }

  // The whole curve as a Bézier spline in the shared model: out_points gets 2·(3·segments + 1)
  // doubles open, 2·3·segments closed; out_tags one tag per junction (C1 where the two knot
  // intervals are equal, G1 with ratio dt_i / dt_{i-1} otherwise, C0 where the tangent vanishes).
  void bezier(std::vector<double>& out_points, std::vector<JunctionInfo>& out_tags) const;

 private:
  int wrap(int i) const {
    return closed_ ? ((i % count_) + count_) % count_ : (i < 0 ? 0 : (i >= count_ ? count_ - 1 : i));
  }
  void rebuild();

  int count_ = 0;
  bool closed_ = false;
  Parameterization param_ = Parameterization::kCentripetal;
  double size_ = 0;
  std::vector<double> points_;      // 2·count
  std::vector<double> dt_;          // segment_count() intervals
  std::vector<double> m_;           // 2·count: Hermite tangents d/dt at each control point
  std::vector<double> override_;    // 2·count: tangent overrides (position units)
  std::vector<char> has_override_;  // count
};

}  // namespace splinekit::edit
