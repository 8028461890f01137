// Shared by the binding files: views of wasm memory and the spline-set handle that every
// capability's bindings take as input. Glue only.
#pragma once

#include <emscripten/bind.h>

#include <string>
#include <vector>

#include "common/bezier.h"
#include "common/spline_set.h"

namespace splinekit {

// A zero-copy view of a vector's storage. It goes stale when the wasm heap grows: JS re-takes
// views after any call that may allocate.
template <class T>
emscripten::val view_of(std::vector<T>& v) {
  return emscripten::val(emscripten::typed_memory_view(v.size(), v.data()));
}

// Status codes shared with src/core/errors.ts (STATUS_CODES there; 0 is success), as the ints
// binding methods return to JS (embind passes an int as a number; a registered enum would cross
// as an object).
inline constexpr int kOk = 0, kInvalidInput = 1, kInternal = 2;

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
  emscripten::val points() { return view_of(set_.points); }
  emscripten::val starts() { return view_of(set_.start); }
  emscripten::val counts() { return view_of(set_.count); }
  emscripten::val closed() { return view_of(set_.closed); }

  // Validates and caches segment/junction totals; every query calls it first.
  int validate() {
    error_ = splinekit::validate(set_);
    return error_.empty() ? kOk : kInvalidInput;
  }
  std::string error() const { return error_; }
  // The set itself, for other capabilities' bindings (validate() first).
  const SplineSet& set() const { return set_; }
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

  emscripten::val result_f64() { return view_of(out_f64_); }
  emscripten::val result_i32() { return view_of(out_i32_); }

 private:
  SplineSet set_;
  std::string error_;
  std::vector<double> out_f64_;
  std::vector<int32_t> out_i32_;
};

}  // namespace splinekit
