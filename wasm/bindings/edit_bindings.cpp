// Embind glue for localized editing of Catmull-Rom curves (wasm/core/edit). No algorithm lives here.
//
// Flow (src/edit/catmull-rom.ts and local-edit.ts drive it):
// - CatmullRomHandle: write x,y pairs into input() after resizeInput(2·n), call set(n, closed,
//   parameterization); or write stroke samples (stride 2..4) and call capture(...). resample(...)
//   and resampleRange(...) replace the curve's points; bezier() fills bezierPoints(),
//   bezierKinds() and bezierRatios().
// - LocalEditHandle: begin(curve, center, left, right, falloff, alpha, sigma, normals), then per
//   frame move(dx, dy) and read points() (allocation-free: the views stay valid between moves);
//   the curve takes the result with applyEdit(edit).
// Status codes as in spline_set_handle.h (0 ok, 1 invalid input); the message is in error().
#include <emscripten/bind.h>

#include <cmath>
#include <string>
#include <vector>

#include "edit/catmull_rom.h"
#include "edit/local_edit.h"
#include "edit/sketch.h"
#include "spline_set_handle.h"

using namespace emscripten;

namespace splinekit::edit {
namespace {

class LocalEditHandle;

class CatmullRomHandle {
 public:
  void resizeInput(int doubles) { input_.assign(size_t(doubles < 0 ? 0 : doubles), 0.0); }
  val input() { return view_of(input_); }

  int set(int count, bool closed, int parameterization) {
    if (count < 0 || 2 * size_t(count) > input_.size())
      return fail("the input holds fewer than " + std::to_string(count) + " points");
    return status(curve_.set(input_.data(), count, closed, Parameterization(parameterization)));
  }
  int capture(int samples, int stride, double min_spacing, bool resample, int parameterization) {
    if (samples < 0 || stride < 0 || size_t(samples) * size_t(stride) > input_.size())
      return fail("the input holds fewer than " + std::to_string(samples) + " samples");
    if (parameterization < 0 || parameterization > 2)
      return fail("parameterization " + std::to_string(parameterization) + " is not uniform, centripetal or chordal");
    CaptureOptions options;
    options.min_spacing = min_spacing;
    options.resample = resample;
    options.parameterization = Parameterization(parameterization);
    if (int s = status(sketch_.capture(input_.data(), samples, stride, options)); s != kOk) return s;
    return status(curve_.set(sketch_.points().data(), sketch_.count(), false, options.parameterization));
  }
  val pressure() { return view_of(const_cast<std::vector<double>&>(sketch_.pressure())); }
  val time() { return view_of(const_cast<std::vector<double>&>(sketch_.time())); }

  int count() const { return curve_.count(); }
  bool closed() const { return curve_.closed(); }
  int parameterization() const { return int(curve_.parameterization()); }
  int segmentCount() const { return curve_.count() == 0 ? 0 : curve_.segment_count(); }
  val points() { return view_of(const_cast<std::vector<double>&>(curve_.points())); }

  int resample(int count) {
    if (int s = status(resampler_.uniform(curve_, count, scratch_)); s != kOk) return s;
    return status(curve_.set(scratch_.data(), count, curve_.closed(), curve_.parameterization()));
  }
  int resampleRange(int first, int last, int inner) {
    if (int s = status(resampler_.range(curve_, first, last, inner, scratch_, new_first_, new_last_)); s != kOk)
      return s;
    return status(curve_.set(scratch_.data(), int(scratch_.size() / 2), curve_.closed(), curve_.parameterization()));
  }
  int newFirst() const { return new_first_; }
  int newLast() const { return new_last_; }

  int bezier() {
    if (curve_.count() == 0) return fail("the curve has no control points");
    std::vector<JunctionInfo> tags;
    curve_.bezier(bezier_, tags);
    kinds_.resize(tags.size());
    ratios_.resize(tags.size());
    for (size_t j = 0; j < tags.size(); ++j) {
      kinds_[j] = int(tags[j].kind);
      ratios_[j] = tags[j].ratio;
    }
    return kOk;
  }
  val bezierPoints() { return view_of(bezier_); }
  val bezierKinds() { return view_of(kinds_); }
  val bezierRatios() { return view_of(ratios_); }

  // Queries write two doubles to out(): a point, a unit normal or a tangent.
  val out() { return view_of(out_); }
  int point(int segment, double u) {
    return write(segment, [&] { return curve_.point(segment, u); });
  }
  int normal(int segment, double u) {
    return write(segment, [&] { return curve_.unit_normal(segment, u); });
  }
  double segmentLength(int segment) { return valid_segment(segment) ? curve_.segment_length(segment) : -1.0; }
  int tangent(int i) {
    if (!valid_point(i)) return kInvalidInput;
    const Vec2 t = curve_.tangent(i);
    out_[0] = t.x(), out_[1] = t.y();
    return kOk;
  }
  int setTangent(int i, double x, double y) {
    if (!valid_point(i)) return kInvalidInput;
    if (!std::isfinite(x) || !std::isfinite(y)) return fail("a tangent needs finite x and y");
    curve_.set_tangent(i, Vec2(x, y));
    return kOk;
  }
  int clearTangent(int i) {
    if (!valid_point(i)) return kInvalidInput;
    curve_.clear_tangent(i);
    return kOk;
  }
  bool tangentOverridden(int i) const { return i >= 0 && i < curve_.count() && curve_.tangent_overridden(i); }

  inline int applyEdit(const LocalEditHandle& edit);
  const CatmullRom& curve() const { return curve_; }
  std::string error() const { return error_; }

 private:
  int fail(const std::string& e) {
    error_ = e;
    return kInvalidInput;
  }
  int status(const std::string& e) { return e.empty() ? kOk : fail(e); }
  bool valid_point(int i) {
    if (i >= 0 && i < curve_.count()) return true;
    fail("control point " + std::to_string(i) + " is out of range (the curve has " + std::to_string(curve_.count()) +
         " control points)");
    return false;
  }
  bool valid_segment(int s) {
    if (curve_.count() > 0 && s >= 0 && s < curve_.segment_count()) return true;
    fail("segment " + std::to_string(s) + " is out of range");
    return false;
  }
  template <class F>
  int write(int segment, F f) {
    if (!valid_segment(segment)) return kInvalidInput;
    const Vec2 v = f();
    out_[0] = v.x(), out_[1] = v.y();
    return kOk;
  }

  CatmullRom curve_;
  SketchCapture sketch_;
  Resampler resampler_;
  std::vector<double> input_, scratch_, bezier_, ratios_, out_ = std::vector<double>(2, 0.0);
  std::vector<int32_t> kinds_;
  int new_first_ = 0, new_last_ = 0;
  std::string error_;
};

class LocalEditHandle {
 public:
  int begin(const CatmullRomHandle& curve, int center, int left, int right, int falloff, double alpha, double sigma,
            bool normals) {
    if (falloff < 0 || falloff > 2)
      return fail("falloff " + std::to_string(falloff) + " is not linear, gaussian or cosine");
    EditOptions options;
    options.left = left;
    options.right = right;
    options.falloff.kind = Falloff(falloff);
    options.falloff.alpha = alpha;
    options.falloff.sigma = sigma;
    options.normals = normals;
    if (std::string e = edit_.begin(curve.curve(), center, options); !e.empty()) return fail(e);
    indices_ = edit_.indices();
    return kOk;
  }
  void move(double dx, double dy) { edit_.move(dx, dy); }
  void end() { edit_.end(); }
  bool active() const { return edit_.active(); }
  val points() { return view_of(const_cast<std::vector<double>&>(edit_.points())); }
  val indices() { return view_of(indices_); }
  val weights() { return view_of(const_cast<std::vector<double>&>(edit_.weights())); }
  val distances() { return view_of(const_cast<std::vector<double>&>(edit_.distances())); }
  int left() const { return edit_.window().left; }
  int right() const { return edit_.window().right; }
  const LocalEdit& edit() const { return edit_; }
  std::string error() const { return error_; }

 private:
  int fail(const std::string& e) {
    error_ = e;
    return kInvalidInput;
  }
  LocalEdit edit_;
  std::vector<int32_t> indices_;
  std::string error_;
};

int CatmullRomHandle::applyEdit(const LocalEditHandle& edit) {
  const std::vector<double>& p = edit.edit().points();
  if (p.size() != curve_.points().size()) return fail("the edit was begun on a curve with another point count");
  curve_.set_points(p.data());
  return kOk;
}

}  // namespace
}  // namespace splinekit::edit

EMSCRIPTEN_BINDINGS(splinekit_edit) {
  using namespace splinekit::edit;
  class_<CatmullRomHandle>("CatmullRomHandle")
      .constructor<>()
      .function("resizeInput", &CatmullRomHandle::resizeInput)
      .function("input", &CatmullRomHandle::input)
      .function("set", &CatmullRomHandle::set)
      .function("capture", &CatmullRomHandle::capture)
      .function("pressure", &CatmullRomHandle::pressure)
      .function("time", &CatmullRomHandle::time)
      .function("count", &CatmullRomHandle::count)
      .function("closed", &CatmullRomHandle::closed)
      .function("parameterization", &CatmullRomHandle::parameterization)
      .function("segmentCount", &CatmullRomHandle::segmentCount)
      .function("points", &CatmullRomHandle::points)
      .function("resample", &CatmullRomHandle::resample)
      .function("resampleRange", &CatmullRomHandle::resampleRange)
      .function("newFirst", &CatmullRomHandle::newFirst)
      .function("newLast", &CatmullRomHandle::newLast)
      .function("bezier", &CatmullRomHandle::bezier)
      .function("bezierPoints", &CatmullRomHandle::bezierPoints)
      .function("bezierKinds", &CatmullRomHandle::bezierKinds)
      .function("bezierRatios", &CatmullRomHandle::bezierRatios)
      .function("out", &CatmullRomHandle::out)
      .function("point", &CatmullRomHandle::point)
      .function("normal", &CatmullRomHandle::normal)
      .function("segmentLength", &CatmullRomHandle::segmentLength)
      .function("tangent", &CatmullRomHandle::tangent)
      .function("setTangent", &CatmullRomHandle::setTangent)
      .function("clearTangent", &CatmullRomHandle::clearTangent)
      .function("tangentOverridden", &CatmullRomHandle::tangentOverridden)
      .function("applyEdit", &CatmullRomHandle::applyEdit)
      .function("error", &CatmullRomHandle::error);
  class_<LocalEditHandle>("LocalEditHandle")
      .constructor<>()
      .function("begin", &LocalEditHandle::begin)
      .function("move", &LocalEditHandle::move)
      .function("end", &LocalEditHandle::end)
      .function("active", &LocalEditHandle::active)
      .function("points", &LocalEditHandle::points)
      .function("indices", &LocalEditHandle::indices)
      .function("weights", &LocalEditHandle::weights)
      .function("distances", &LocalEditHandle::distances)
      .function("left", &LocalEditHandle::left)
      .function("right", &LocalEditHandle::right)
      .function("error", &LocalEditHandle::error);
}
