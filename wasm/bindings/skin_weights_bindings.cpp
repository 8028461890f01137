// Embind glue for automatic skinning weights on a 2D mesh (wasm/core/skin/weights.h): harmonic
// and bounded biharmonic weights, and their evaluation at arbitrary points (point_location.h).
// No algorithm here.
//
// Flow (src/skin/weights.ts): resize(#V, #F, #H); fill vertices(), triangles(), handles();
// harmonic() or bbw(...) — each validates, solves and builds the point locator; read weights().
// Then per query batch: resizeQueries(#P), fill queries(), weightsAt() / gradientsAt(), read
// result(). Methods returning int return a status (0 = ok, see src/core/errors.ts) and leave the
// message in error(); a failed solve keeps the previous weights.
#include <emscripten/bind.h>

#include <cmath>
#include <string>
#include <vector>

#include "skin/operators.h"
#include "skin/point_location.h"
#include "skin/weights.h"
#include "spline_set_handle.h"

using namespace emscripten;

namespace splinekit::skin {
namespace {

class SkinWeightsHandle {
 public:
  // Sizes the mesh and handle arrays (zeroed); forgets any weights.
  void resize(int vertices, int triangles, int handles) {
    vertices_.assign(2 * size_t(std::max(vertices, 0)), 0.0);
    triangles_.assign(3 * size_t(std::max(triangles, 0)), 0);
    handles_.assign(size_t(std::max(handles, 0)), 0);
    weights_.clear();
    gradients_.clear();
    iterations_.clear();
  }
  val vertices() { return view_of(vertices_); }
  val triangles() { return view_of(triangles_); }
  val handles() { return view_of(handles_); }

  int harmonic() {
    std::vector<double> W(weight_count());
    return finish(harmonic_weights(mesh(), handles_.data(), handle_count(), W.data()), W);
  }

  // mass: 0 barycentric, 1 Voronoi (MassType).
  int bbw(int max_iterations, double bound_tolerance, double multiplier_tolerance, bool partition_of_unity, int mass) {
    BbwOptions options;
    options.max_iterations = max_iterations;
    options.bound_tolerance = bound_tolerance;
    options.multiplier_tolerance = multiplier_tolerance;
    options.partition_of_unity = partition_of_unity;
    options.mass = mass == 0 ? MassType::kBarycentric : MassType::kVoronoi;
    std::vector<double> W(weight_count());
    return finish(bbw_weights(mesh(), handles_.data(), handle_count(), options, W.data()), W);
  }

  std::string error() const { return error_; }
  int handle_count() const { return int(handles_.size()); }
  val weights() { return view_of(weights_); }               // #V by #H
  val triangle_gradients() { return view_of(gradients_); }  // #F by #H by 2
  val iterations() { return view_of(iterations_); }         // BBW: linear solves per handle
  bool converged() const { return converged_; }
  int pinned() const { return pinned_; }

  void resize_queries(int points) { queries_.assign(2 * size_t(std::max(points, 0)), 0.0); }
  val queries() { return view_of(queries_); }

  // Weights at the query points into result(): #P by #H.
  int weights_at() {
    if (int status = check_queries(); status != kOk) return status;
    const int P = int(queries_.size() / 2);
    out_.resize(size_t(P) * handle_count());
    locate_and_interpolate(grid_, mesh(), weights_.data(), handle_count(), queries_.data(), P, out_.data());
    return kOk;
  }

  // Gradients at the query points into result(): #P by #H by 2.
  int gradients_at() {
    if (int status = check_queries(); status != kOk) return status;
    const int P = int(queries_.size() / 2);
    out_.resize(size_t(P) * handle_count() * 2);
    locate_gradients(grid_, mesh(), gradients_.data(), handle_count(), queries_.data(), P, out_.data());
    return kOk;
  }
  val result() { return view_of(out_); }

 private:
  MeshView2 mesh() const {
    return {vertices_.data(), int(vertices_.size() / 2), triangles_.data(), int(triangles_.size() / 3)};
  }
  size_t weight_count() const { return vertices_.size() / 2 * handles_.size(); }

  // Keeps a successful solve's weights, their gradients and the point locator.
  int finish(const WeightsReport& report, std::vector<double>& W) {
    if (!report.ok()) {
      error_ = report.error;
      return report.error.rfind("internal", 0) == 0 ? kInternal : kInvalidInput;
    }
    weights_.swap(W);
    gradients_.resize(triangles_.size() / 3 * handles_.size() * 2);
    triangle_weight_gradients(mesh(), weights_.data(), handle_count(), gradients_.data());
    build_triangle_grid(mesh(), grid_);
    iterations_.assign(report.iterations.begin(), report.iterations.end());
    converged_ = report.converged;
    pinned_ = report.pinned;
    return kOk;
  }

  int check_queries() {
    if (weights_.empty()) {
      error_ = "no weights yet: call harmonic() or bbw() first";
      return kInvalidInput;
    }
    for (size_t k = 0; k < queries_.size(); ++k)
      if (!std::isfinite(queries_[k])) {
        error_ = "query point " + std::to_string(k / 2) + " has a non-finite coordinate";
        return kInvalidInput;
      }
    return kOk;
  }

  std::vector<double> vertices_, weights_, gradients_, queries_, out_;
  std::vector<int32_t> triangles_, handles_, iterations_;
  TriangleGrid grid_;
  std::string error_;
  bool converged_ = true;
  int pinned_ = 0;
};

}  // namespace
}  // namespace splinekit::skin

EMSCRIPTEN_BINDINGS(splinekit_skin_weights) {
  using namespace splinekit::skin;
  class_<SkinWeightsHandle>("SkinWeightsHandle")
      .constructor<>()
      .function("resize", &SkinWeightsHandle::resize)
      .function("vertices", &SkinWeightsHandle::vertices)
      .function("triangles", &SkinWeightsHandle::triangles)
      .function("handles", &SkinWeightsHandle::handles)
      .function("harmonic", &SkinWeightsHandle::harmonic)
      .function("bbw", &SkinWeightsHandle::bbw)
      .function("error", &SkinWeightsHandle::error)
      .function("handleCount", &SkinWeightsHandle::handle_count)
      .function("weights", &SkinWeightsHandle::weights)
      .function("triangleGradients", &SkinWeightsHandle::triangle_gradients)
      .function("iterations", &SkinWeightsHandle::iterations)
      .function("converged", &SkinWeightsHandle::converged)
      .function("pinned", &SkinWeightsHandle::pinned)
      .function("resizeQueries", &SkinWeightsHandle::resize_queries)
      .function("queries", &SkinWeightsHandle::queries)
      .function("weightsAt", &SkinWeightsHandle::weights_at)
      .function("gradientsAt", &SkinWeightsHandle::gradients_at)
      .function("result", &SkinWeightsHandle::result);
}
