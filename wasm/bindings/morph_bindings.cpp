// Embind glue for shape blending (wasm/core/morph/morph.h). No algorithm lives here.
//
// Flow (src/morph/morph.ts drives it): resizePins(n) and write pins() (ax, ay, bx, by per pin);
// setup(a, b, options...) with two validated spline sets, an unset (NaN) option taking the core's
// default; then read the layout (starts/counts/closed/coupled), work() and contours(). Per frame:
// evaluate(t, mode) and read points() — no allocation, so the view stays valid between frames.
#include <emscripten/bind.h>

#include <cmath>
#include <string>
#include <vector>

#include "morph/morph.h"
#include "spline_set_handle.h"

using namespace emscripten;

namespace splinekit::morph {
namespace {

class MorphHandle {
 public:
  void resize_pins(int n) { pins_.assign(4 * size_t(n < 0 ? 0 : n), 0.0); }
  val pins() { return view_of(pins_); }

  // Options: NaN leaves the core's default; direction < 0 likewise (0 winding, 1 both, 2 forward).
  int setup(SplineSetHandle& a, SplineSetHandle& b, double stretching, double bending, double kinking,
            double kink_exponent, double segment_limit, double continuity_tolerance, double length_unit, double travel,
            int direction) {
    if (a.validate() != kOk) return fail("the first shape: " + a.error());
    if (b.validate() != kOk) return fail("the second shape: " + b.error());
    MorphOptions o;
    auto set = [](double v, double& field) {
      if (!std::isnan(v)) field = v;
    };
    set(stretching, o.work.stretching);
    set(bending, o.work.bending);
    set(kinking, o.work.kinking);
    set(kink_exponent, o.work.kink_exponent);
    set(segment_limit, o.segment_limit);
    set(continuity_tolerance, o.continuity_tolerance);
    set(length_unit, o.length_unit);
    set(travel, o.work.travel);
    if (direction >= 0 && direction <= 2) o.direction = Direction(direction);
    std::vector<MorphPin> pins(pins_.size() / 4);
    for (size_t k = 0; k < pins.size(); ++k)
      pins[k] = {pins_[4 * k], pins_[4 * k + 1], pins_[4 * k + 2], pins_[4 * k + 3]};
    if (std::string e = morph_.setup(a.set(), b.set(), o, pins); !e.empty()) return fail(e);
    points_.assign(2 * size_t(morph_.point_count()), 0.0);
    coupled_.assign(morph_.coupled().begin(), morph_.coupled().end());
    contours_.clear();
    for (const BlendedContour& c : morph_.contours()) {
      contours_.insert(contours_.end(), {double(c.contour_a), double(c.contour_b), c.work, double(c.start),
                                         c.reversed ? 1.0 : 0.0, double(c.pins)});
    }
    return kOk;
  }

  // mode: 0 linear, 1 intrinsic.
  int evaluate(double t, int mode) {
    if (!std::isfinite(t)) return fail("t must be a finite number");
    if (points_.empty()) return fail("the morph has not been set up");
    morph_.evaluate(t, mode == 1 ? Interpolation::kIntrinsic : Interpolation::kLinear, points_.data());
    return kOk;
  }
  val points() { return view_of(points_); }
  val starts() { return view_of(const_cast<std::vector<int32_t>&>(morph_.starts())); }
  val counts() { return view_of(const_cast<std::vector<int32_t>&>(morph_.counts())); }
  val closed() { return view_of(const_cast<std::vector<int32_t>&>(morph_.closed())); }
  val coupled() { return view_of(coupled_); }
  // Six numbers per output contour: contour of A (−1: grows), of B (−1: shrinks), work, start, reversed, pins.
  val contours() { return view_of(contours_); }
  int contourCount() const { return morph_.contour_count(); }
  int pointCount() const { return morph_.point_count(); }
  double work() const { return morph_.work(); }
  double cells() const { return double(morph_.counters().cells); }
  std::string error() const { return error_; }

 private:
  int fail(const std::string& e) {
    error_ = e;
    return kInvalidInput;
  }
  Morph morph_;
  std::vector<double> pins_, points_, contours_;
  std::vector<int32_t> coupled_;
  std::string error_;
};

}  // namespace
}  // namespace splinekit::morph

EMSCRIPTEN_BINDINGS(splinekit_morph) {
  using namespace splinekit::morph;
  class_<MorphHandle>("MorphHandle")
      .constructor<>()
      .function("resizePins", &MorphHandle::resize_pins)
      .function("pins", &MorphHandle::pins)
      .function("setup", &MorphHandle::setup)
      .function("evaluate", &MorphHandle::evaluate)
      .function("points", &MorphHandle::points)
      .function("starts", &MorphHandle::starts)
      .function("counts", &MorphHandle::counts)
      .function("closed", &MorphHandle::closed)
      .function("coupled", &MorphHandle::coupled)
      .function("contours", &MorphHandle::contours)
      .function("contourCount", &MorphHandle::contourCount)
      .function("pointCount", &MorphHandle::pointCount)
      .function("work", &MorphHandle::work)
      .function("cells", &MorphHandle::cells)
      .function("error", &MorphHandle::error);
}
