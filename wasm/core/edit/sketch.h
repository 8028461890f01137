// splinekit — from a pointer stroke to Catmull-Rom control points, and resampling by arc length
// (Eyiyurekli & Breen §3 and §3.2, multi-resolution control).
//
// SketchCapture keeps the stroke's samples as control points (their density follows the hand's
// speed, as in the paper), dropping repeats closer than a minimum spacing, with the pressure and
// time of each kept sample. Resampler places control points evenly by arc length along a curve:
// over the whole curve with the same count (§3.2's uniform resampling), or between two control
// points at a chosen resolution (re-resampling inside the active window; the rest stays).
#pragma once

#include <string>
#include <vector>

#include "edit/catmull_rom.h"

namespace splinekit::edit {

// ---------------------------------------------------------------------------------------------
// Arc length of a Catmull-Rom curve, tabulated for inversion
// ---------------------------------------------------------------------------------------------

// Cumulative arc length at kSub evenly spaced parameters of each segment (3-point Gauss–Legendre
// per sub-interval), and the inverse: the (segment, u) at a given arc length.
class ArcLengthTable {
 public:
  static constexpr int kSub = 8;
  // Tabulates segments [first, first + segments) of `curve` (indices wrap on a closed curve).
  void build(const CatmullRom& curve, int first, int segments);
  double total() const { return cum_.empty() ? 0.0 : cum_.back(); }
  // The parameter at arc length s from the table's start (clamped to [0, total()]): segment index
  // (relative to `first`) and u in [0, 1]. Two Newton steps refine the tabulated guess.
  void locate(double s, int& segment, double& u) const;

 private:
  double partial(int segment, double ua, double ub) const;  // length of relative segment over [ua, ub]
  std::vector<double> seg_;                                 // 8 doubles per tabulated segment (its Bézier form)
  std::vector<double> cum_;                                 // kSub·segments + 1 cumulative lengths
};

// ---------------------------------------------------------------------------------------------
// Sketch capture
// ---------------------------------------------------------------------------------------------

struct CaptureOptions {
  // A sample closer than this to the last kept one is dropped (drawing units; 0 drops exact repeats only).
  double min_spacing = 0.0;
  // Replace the kept samples by as many control points evenly spaced by arc length (§3.2).
  bool resample = false;
  Parameterization parameterization = Parameterization::kCentripetal;
};

class SketchCapture {
 public:
  // samples: n·stride doubles, x y [pressure [time]] per sample (stride 2, 3 or 4). Returns "" or a
  // message naming the problem (bad stride, a non-finite sample, fewer than 2 distinct points).
  std::string capture(const double* samples, int n, int stride, const CaptureOptions& options);
  const std::vector<double>& points() const { return points_; }      // 2 per control point
  const std::vector<double>& pressure() const { return pressure_; }  // 1 per control point (1 when absent)
  const std::vector<double>& time() const { return time_; }          // 1 per control point (the index when absent)
  int count() const { return int(pressure_.size()); }

 private:
  std::vector<double> points_, pressure_, time_, kept_;
  CatmullRom curve_;
  ArcLengthTable table_;
};

// ---------------------------------------------------------------------------------------------
// Resampling
// ---------------------------------------------------------------------------------------------

class Resampler {
 public:
  // `count` points evenly spaced by arc length over the whole curve (open: both ends kept; closed:
  // starting at point 0), into out (2·count doubles). Also per point in `at`: segment + u, so
  // per-point attributes can be interpolated. count >= 2 (3 closed).
  std::string uniform(const CatmullRom& curve, int count, std::vector<double>& out);
  // Replaces the points strictly between control points `first` and `last` (going forward; on a
  // closed curve the window may wrap, and first == last means the whole loop) by `inner` points
  // evenly spaced by arc length between them. out gets the new curve's points; new_first and
  // new_last the window ends' new indices. An open curve keeps its order; a closed curve whose
  // window wraps is rotated to start at `last`.
  std::string range(const CatmullRom& curve, int first, int last, int inner, std::vector<double>& out, int& new_first,
                    int& new_last);
  // After uniform(): the curve parameter of each new point, segment + u.
  const std::vector<double>& parameters() const { return at_; }

 private:
  ArcLengthTable table_;
  std::vector<double> at_;
};

}  // namespace splinekit::edit
