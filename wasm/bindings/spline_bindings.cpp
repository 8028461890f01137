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
#include "spline_set_handle.h"

using namespace emscripten;

namespace splinekit {
namespace {

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
