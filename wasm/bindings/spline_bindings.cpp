// Embind glue for the spline kernels (wasm/core/common). No algorithm lives here.
//
// Conventions for every binding file:
// - Data crosses as flat typed arrays: the JS side writes into views of wasm memory
//   (typed_memory_view), calls a method, and reads results from views. Views go stale when the
//   heap grows, so JS re-takes them after any call that may allocate.
// - No C++ exception crosses the boundary: methods return a status (0 = ok) and the message is
//   kept in `error()`; the TS layer turns it into a SplinekitError.
#include <emscripten/bind.h>

#include <string>
#include <vector>

#include "common/bezier.h"
#include "common/continuity.h"
#include "common/spline_set.h"

using namespace emscripten;

namespace splinekit {
namespace {

template <class T>
val view_of(std::vector<T>& v) {
  return val(typed_memory_view(v.size(), v.data()));
}

// Status codes shared with src/core/errors.ts.
enum Status : int { kOk = 0, kInvalidInput = 1, kInternal = 2 };

class SplineSetHandle {
 public:
  // Sizes the arrays for `splines` splines over `points` points; contents are zeroed.
  void resize(int splines, int points) {
    set_.points.assign(2 * size_t(points < 0 ? 0 : points), 0.0);
    const size_t n = splines < 0 ? 0 : size_t(splines);
    set_.start.assign(n, 0);
    set_.count.assign(n, 0);
    set_.closed.assign(n, 0);
  }
  val points() { return view_of(set_.points); }
  val starts() { return view_of(set_.start); }
  val counts() { return view_of(set_.count); }
  val closed() { return view_of(set_.closed); }

  // Validates and caches segment/junction totals; every query calls it first.
  int validate() {
    error_ = splinekit::validate(set_);
    return error_.empty() ? kOk : kInvalidInput;
  }
  std::string error() const { return error_; }
  int segment_count() const { return total_segments(set_); }
  int junction_count() const { return total_junctions(set_); }

  int bounds() {
    if (validate() != kOk) return kInvalidInput;
    out_f64_.resize(4 * size_t(set_.spline_count()));
    spline_set_bounds(set_, out_f64_.data());
    return kOk;
  }

  // Results in kinds (Continuity as int), and in f64 as ratio,angle pairs.
  int classify(double length_tolerance, double angle_tolerance, double ratio_tolerance) {
    if (validate() != kOk) return kInvalidInput;
    ContinuityOptions options;
    options.length_tolerance = length_tolerance;
    options.angle_tolerance = angle_tolerance;
    options.ratio_tolerance = ratio_tolerance;
    std::vector<JunctionInfo> info(size_t(total_junctions(set_)));
    spline_set_classify(set_, options, info.data());
    out_i32_.resize(info.size());
    out_f64_.resize(2 * info.size());
    for (size_t j = 0; j < info.size(); ++j) {
      out_i32_[j] = int(info[j].kind);
      out_f64_[2 * j] = info[j].ratio;
      out_f64_[2 * j + 1] = info[j].angle;
    }
    return kOk;
  }

  int sample(int per_segment) {
    if (validate() != kOk) return kInvalidInput;
    if (per_segment < 2 || per_segment > 100000) {
      error_ = "samples per segment must be in [2, 100000], got " + std::to_string(per_segment);
      return kInvalidInput;
    }
    out_f64_.resize(2 * size_t(per_segment) * size_t(total_segments(set_)));
    spline_set_sample(set_, per_segment, out_f64_.data());
    return kOk;
  }

  // Arc length of every segment (spline by spline) to absolute tolerance tol.
  int segment_lengths(double tol) {
    if (validate() != kOk) return kInvalidInput;
    out_f64_.resize(size_t(total_segments(set_)));
    double seg[8];
    size_t k = 0;
    for (int s = 0; s < set_.spline_count(); ++s) {
      const bool c = set_.closed[s] != 0;
      for (int i = 0; i < spline_segment_count(set_.count[s], c); ++i) {
        spline_segment(set_.spline_points(s), set_.count[s], c, i, seg);
        out_f64_[k++] = bezier_arc_length(seg, 0.0, 1.0, tol);
      }
    }
    return kOk;
  }

  val result_f64() { return view_of(out_f64_); }
  val result_i32() { return view_of(out_i32_); }

 private:
  SplineSet set_;
  std::string error_;
  std::vector<double> out_f64_;
  std::vector<int32_t> out_i32_;
};

// Single-segment kernels on a scratch buffer of 16 doubles: input segment in [0,8).
class BezierScratch {
 public:
  BezierScratch() : data_(16, 0.0) {}
  val data() { return view_of(data_); }
  // Point (order 0) or derivative at t into [8,10).
  void derivative(double t, int order) {
    const Vec2 v = bezier_derivative(data_.data(), t, order);
    data_[8] = v.x();
    data_[9] = v.y();
  }
  // Split at t: left half into [0,8), right half into [8,16).
  void split(double t) {
    double seg[8], l[8], r[8];
    std::copy(data_.begin(), data_.begin() + 8, seg);
    bezier_split(seg, t, l, r);
    std::copy(l, l + 8, data_.begin());
    std::copy(r, r + 8, data_.begin() + 8);
  }
  double arc_length(double t0, double t1, double tol) { return bezier_arc_length(data_.data(), t0, t1, tol); }
  // Bounds into [8,12).
  void bounds() { bezier_bounds(data_.data(), data_.data() + 8); }

 private:
  std::vector<double> data_;
};

val gram_matrix() {
  const Eigen::Matrix4d g = bernstein_gram();
  val out = val::array();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out.call<void>("push", g(i, j));
  return out;
}

}  // namespace
}  // namespace splinekit

EMSCRIPTEN_BINDINGS(splinekit_spline) {
  using namespace splinekit;
  class_<SplineSetHandle>("SplineSetHandle")
      .constructor<>()
      .function("resize", &SplineSetHandle::resize)
      .function("points", &SplineSetHandle::points)
      .function("starts", &SplineSetHandle::starts)
      .function("counts", &SplineSetHandle::counts)
      .function("closed", &SplineSetHandle::closed)
      .function("validate", &SplineSetHandle::validate)
      .function("error", &SplineSetHandle::error)
      .function("segmentCount", &SplineSetHandle::segment_count)
      .function("junctionCount", &SplineSetHandle::junction_count)
      .function("bounds", &SplineSetHandle::bounds)
      .function("classify", &SplineSetHandle::classify)
      .function("sample", &SplineSetHandle::sample)
      .function("segmentLengths", &SplineSetHandle::segment_lengths)
      .function("resultF64", &SplineSetHandle::result_f64)
      .function("resultI32", &SplineSetHandle::result_i32);
  class_<BezierScratch>("BezierScratch")
      .constructor<>()
      .function("data", &BezierScratch::data)
      .function("derivative", &BezierScratch::derivative)
      .function("split", &BezierScratch::split)
      .function("arcLength", &BezierScratch::arc_length)
      .function("bounds", &BezierScratch::bounds);
  function("gramMatrix", &gram_matrix);
}
