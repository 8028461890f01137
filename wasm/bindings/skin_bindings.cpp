// Embind glue for the skinning rig (wasm/core/skin/rig.h). No algorithm lives here.
//
// Flow (src/skin/rig.ts drives it): setup(splineSet, handleCount, samples) after writing the
// junction kinds into kinds(); then either useShepard(power) after writing handles(), or write
// sampleWeights() / pointWeights() / pointGradients() computed elsewhere (harmonic, BBW); then
// precompute(). Per frame: write transforms(), call update(), read points(). None of the
// per-frame calls allocates, so the views stay valid between them.
#include <emscripten/bind.h>

#include <string>
#include <vector>

#include "skin/rig.h"
#include "spline_set_handle.h"

using namespace emscripten;

namespace splinekit::skin {
namespace {

class SkinRigHandle {
 public:
  // Junction kinds (Continuity as int32) to fill before setup().
  void resize_kinds(int n) { kinds_.assign(size_t(n < 0 ? 0 : n), int(Continuity::kC0)); }
  val kinds() { return view_of(kinds_); }

  int setup(const SplineSetHandle& splines, int handle_count, int samples) {
    std::vector<Continuity> kinds;
    for (int k : kinds_) {
      if (k < 0 || k > int(Continuity::kAngle))
        return fail("junction kind " + std::to_string(k) + " is not a continuity tag");
      kinds.push_back(Continuity(k));
    }
    SkinOptions options;
    options.samples = samples;
    if (std::string e = rig_.setup(splines.set(), kinds, handle_count, options); !e.empty()) return fail(e);
    handles_.assign(2 * size_t(handle_count), 0.0);
    transforms_.assign(6 * size_t(handle_count), 0.0);
    for (int i = 0; i < handle_count; ++i) transforms_[6 * i] = transforms_[6 * i + 3] = 1.0;
    per_curve_.assign(size_t(rig_.curve_count()), 0.0);
    return kOk;
  }

  val handles() { return view_of(handles_); }
  val samplePoints() { return view_of(const_cast<std::vector<double>&>(rig_.sample_points())); }
  val controlPoints() { return view_of(const_cast<std::vector<double>&>(rig_.control_points())); }
  val sampleWeights() { return view_of(rig_.sample_weights()); }
  val pointWeights() { return view_of(rig_.point_weights()); }
  val pointGradients() { return view_of(rig_.point_gradients()); }

  void useShepard(double power) { rig_.use_shepard(handles_.data(), power); }

  int precompute() {
    if (std::string e = rig_.precompute(); !e.empty()) return fail(e);
    return kOk;
  }

  val transforms() { return view_of(transforms_); }
  void update() { rig_.update(transforms_.data()); }
  val points() { return view_of(const_cast<std::vector<double>&>(rig_.points())); }

  // Baseline control points for the current transforms (method: 1 all, 2 interpolated, 3 Jacobian).
  val baseline(int method) {
    const double* p = rig_.baseline(SkinMethod(method), transforms_.data());
    return val(typed_memory_view(rig_.control_points().size(), p));
  }

  // Flexible relax from the rigid fit for the current transforms; energies in relaxEnergies().
  int relax() {
    const RelaxReport r = rig_.relax(transforms_.data());
    energies_ = r.energies;
    return r.iterations;
  }
  val relaxEnergies() { return view_of(energies_); }

  // Error of the fit (method 0) or a baseline for the current transforms: per curve in
  // perCurveError(), total returned.
  double error(int method) {
    const double* p = method == 0 ? rig_.points().data() : rig_.baseline(SkinMethod(method), transforms_.data());
    return rig_.error(p, transforms_.data(), per_curve_.data());
  }
  val perCurveError() { return view_of(per_curve_); }
  double constraintResidual() { return rig_.constraint_residual(rig_.points().data()); }

  int curveCount() const { return rig_.curve_count(); }
  int constrainedCount() const { return rig_.constrained_count(); }
  double totalLength() const { return rig_.total_length(); }
  std::string error_message() const { return error_; }

 private:
  int fail(const std::string& e) {
    error_ = e;
    return kInvalidInput;
  }
  SkinRig rig_;
  std::vector<int32_t> kinds_;
  std::vector<double> handles_, transforms_, per_curve_, energies_;
  std::string error_;
};

}  // namespace
}  // namespace splinekit::skin

EMSCRIPTEN_BINDINGS(splinekit_skin) {
  using namespace splinekit::skin;
  class_<SkinRigHandle>("SkinRigHandle")
      .constructor<>()
      .function("resizeKinds", &SkinRigHandle::resize_kinds)
      .function("kinds", &SkinRigHandle::kinds)
      .function("setup", &SkinRigHandle::setup)
      .function("handles", &SkinRigHandle::handles)
      .function("samplePoints", &SkinRigHandle::samplePoints)
      .function("controlPoints", &SkinRigHandle::controlPoints)
      .function("sampleWeights", &SkinRigHandle::sampleWeights)
      .function("pointWeights", &SkinRigHandle::pointWeights)
      .function("pointGradients", &SkinRigHandle::pointGradients)
      .function("useShepard", &SkinRigHandle::useShepard)
      .function("precompute", &SkinRigHandle::precompute)
      .function("transforms", &SkinRigHandle::transforms)
      .function("update", &SkinRigHandle::update)
      .function("points", &SkinRigHandle::points)
      .function("baseline", &SkinRigHandle::baseline)
      .function("relax", &SkinRigHandle::relax)
      .function("relaxEnergies", &SkinRigHandle::relaxEnergies)
      .function("error", &SkinRigHandle::error)
      .function("perCurveError", &SkinRigHandle::perCurveError)
      .function("constraintResidual", &SkinRigHandle::constraintResidual)
      .function("curveCount", &SkinRigHandle::curveCount)
      .function("constrainedCount", &SkinRigHandle::constrainedCount)
      .function("totalLength", &SkinRigHandle::totalLength)
      .function("errorMessage", &SkinRigHandle::error_message);
}
