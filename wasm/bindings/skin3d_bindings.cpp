// Embind glue for the subdivision-surface skinning rig (wasm/core/skin3d/rig.h). No algorithm
// lives here.
//
// Flow (src/skin3d/rig.ts drives it): resize(vertices, faceIndices, faces, creases), fill
// positionsIn(), faceSizesIn(), faceIndicesIn(), creaseEdgesIn() (2 per crease, 0-based) and
// creaseSharpnessIn(), and with corner tags resizeCorners(n), cornerVerticesIn(),
// cornerSharpnessIn(); setup(levels, handleCount). Weights: write handles() then useShepard(power)
// or bbw(level, ..., onHandle), or write refinedWeights() (and restrictWeights()) or cageWeights() (and
// prolongateWeights()); then precompute(). Per frame: write transforms() (12 per handle), call
// update(), read cage(). The per-frame calls allocate nothing, so views stay valid between them.
#include <emscripten/bind.h>

#include <string>
#include <vector>

#include "skin3d/rig.h"
#include "skin3d/weights.h"
#include "spline_set_handle.h"

using namespace emscripten;

namespace splinekit::skin3d {
namespace {

class Skin3dRigHandle {
 public:
  void resize(int vertices, int face_indices, int faces, int creases) {
    positions_.assign(3 * size_t(std::max(vertices, 0)), 0.0);
    face_indices_.assign(size_t(std::max(face_indices, 0)), 0);
    face_sizes_.assign(size_t(std::max(faces, 0)), 0);
    crease_edges_.assign(2 * size_t(std::max(creases, 0)), 0);
    crease_sharpness_.assign(size_t(std::max(creases, 0)), 0.0);
    corner_vertices_.clear(), corner_sharpness_.clear();
  }
  val positionsIn() { return view_of(positions_); }
  val faceSizesIn() { return view_of(face_sizes_); }
  val faceIndicesIn() { return view_of(face_indices_); }
  val creaseEdgesIn() { return view_of(crease_edges_); }
  val creaseSharpnessIn() { return view_of(crease_sharpness_); }
  // Corner tags (after resize, which clears them): 0-based vertices and their sharpness.
  void resizeCorners(int corners) {
    corner_vertices_.assign(size_t(std::max(corners, 0)), 0);
    corner_sharpness_.assign(size_t(std::max(corners, 0)), 0.0);
  }
  val cornerVerticesIn() { return view_of(corner_vertices_); }
  val cornerSharpnessIn() { return view_of(corner_sharpness_); }

  int setup(int levels, int handle_count) {
    std::vector<Crease> creases(crease_sharpness_.size());
    for (size_t k = 0; k < creases.size(); ++k)
      creases[k] = {crease_edges_[2 * k], crease_edges_[2 * k + 1], crease_sharpness_[k]};
    int total = 0;
    for (int n : face_sizes_) total += n;
    if (total != int(face_indices_.size()))
      return fail("face sizes add up to " + std::to_string(total) + " indices, got " +
                  std::to_string(face_indices_.size()));
    const std::vector<Corner> corners = corner_tags();
    const std::string e = rig_.setup(positions_.data(), int(positions_.size() / 3), face_sizes_.data(),
                                     int(face_sizes_.size()), face_indices_.data(), creases.data(), int(creases.size()),
                                     levels, handle_count, corners.data(), int(corners.size()));
    if (!e.empty()) return fail(e);
    handles_.assign(3 * size_t(handle_count), 0.0);
    transforms_.assign(12 * size_t(handle_count), 0.0);
    for (int i = 0; i < handle_count; ++i)
      transforms_[12 * i] = transforms_[12 * i + 5] = transforms_[12 * i + 10] = 1.0;
    cage_in_.assign(positions_.size(), 0.0);
    per_vertex_.assign(size_t(rig_.refined_vertex_count()), 0.0);
    return kOk;
  }

  // The inputs refined `levels` times as a cage of its own (instead of setup): positions,
  // quads and crease tags (sharpness decayed by `levels`) in refinedCage*().
  int refineCage(int levels) {
    if (levels < 1 || levels > 4) return fail("levels must be in 1..4, got " + std::to_string(levels));
    PolyMesh cage;
    if (std::string e = make_poly_mesh(int(positions_.size() / 3), face_sizes_.data(), int(face_sizes_.size()),
                                       face_indices_.data(), cage);
        !e.empty())
      return fail(e);
    std::vector<Crease> creases(crease_sharpness_.size());
    for (size_t k = 0; k < creases.size(); ++k)
      creases[k] = {crease_edges_[2 * k], crease_edges_[2 * k + 1], crease_sharpness_[k]};
    if (std::string e = apply_creases(creases.data(), int(creases.size()), cage); !e.empty()) return fail(e);
    const std::vector<Corner> corners = corner_tags();
    if (std::string e = apply_corners(corners.data(), int(corners.size()), cage); !e.empty()) return fail(e);
    Subdivision s;
    s.build(cage, levels, true);
    const PolyMesh& fine = s.refined_mesh();
    out_positions_.assign(3 * size_t(fine.vertex_count), 0.0);
    s.apply(positions_.data(), 3, out_positions_.data());
    out_faces_ = fine.face_vertices;
    out_crease_edges_.clear();
    out_crease_sharpness_.clear();
    for (int e = 0; e < fine.edge_count(); ++e)
      if (!fine.boundary_edge(e) && fine.edge_sharpness[e] > 0) {
        out_crease_edges_.insert(out_crease_edges_.end(), {fine.edge_vertices[2 * e], fine.edge_vertices[2 * e + 1]});
        out_crease_sharpness_.push_back(fine.edge_sharpness[e]);
      }
    out_corner_vertices_.clear();
    out_corner_sharpness_.clear();
    for (int v = 0; v < fine.vertex_count; ++v)
      if (fine.vertex_sharpness[v] > 0)
        out_corner_vertices_.push_back(v), out_corner_sharpness_.push_back(fine.vertex_sharpness[v]);
    return kOk;
  }
  val refinedCagePositions() { return view_of(out_positions_); }
  val refinedCageQuads() { return view_of(out_faces_); }
  val refinedCageCreaseEdges() { return view_of(out_crease_edges_); }
  val refinedCageCreaseSharpness() { return view_of(out_crease_sharpness_); }
  val refinedCageCornerVertices() { return view_of(out_corner_vertices_); }
  val refinedCageCornerSharpness() { return view_of(out_corner_sharpness_); }

  val handles() { return view_of(handles_); }
  void useShepard(double power) { rig_.use_shepard(handles_.data(), power); }
  // on_handle: a JS function (solved, total) called after each handle's solve, or undefined.
  int bbw(int level, int max_iterations, double multiplier_tolerance, val on_handle) {
    skin::BbwOptions options;
    options.max_iterations = max_iterations;
    options.multiplier_tolerance = multiplier_tolerance;
    if (!on_handle.isUndefined() && !on_handle.isNull())
      options.on_handle_solved = [&on_handle](int solved, int total) { on_handle(solved, total); };
    const skin::WeightsReport r = surface_bbw_weights(rig_, handles_.data(), level, options);
    if (!r.ok()) return fail(r.error);
    return kOk;
  }
  int bbwLevel(int max_vertices) const { return bbw_level(rig_, max_vertices); }
  val refinedWeights() { return view_of(rig_.refined_weights()); }
  val cageWeights() { return view_of(rig_.cage_weights()); }
  void prolongateWeights() { rig_.prolongate_cage_weights(); }
  void restrictWeights() { rig_.restrict_refined_weights(); }

  int precompute() {
    if (std::string e = rig_.precompute(); !e.empty()) return fail(e);
    return kOk;
  }

  val transforms() { return view_of(transforms_); }
  void update() { rig_.update(transforms_.data()); }
  val cage() { return view_of(const_cast<std::vector<double>&>(rig_.cage())); }
  // Naive LBS of the cage vertices for the current transforms (a view of the rig's buffer).
  val naive() { return val(typed_memory_view(positions_.size(), rig_.naive(transforms_.data()))); }
  // A cage to subdivide (#cage by 3).
  val cageIn() { return view_of(cage_in_); }
  // M · (source: 0 the fit, 1 the naive cage, 2 cageIn()).
  val refine(int source) { return val(typed_memory_view(rig_.refined().size(), rig_.refine(source_cage(source)))); }
  // Limit positions of the level-k vertices of M · (source).
  val limit(int source) { return val(typed_memory_view(rig_.refined().size(), rig_.limit(source_cage(source)))); }
  val target() { return val(typed_memory_view(rig_.refined().size(), rig_.target(transforms_.data()))); }
  // Error of M · (source) against the target, per refined vertex into perVertexError().
  double error(int source) { return rig_.error(source_cage(source), transforms_.data(), per_vertex_.data()); }
  val perVertexError() { return view_of(per_vertex_); }

  val restRefined() { return view_of(const_cast<std::vector<double>&>(rig_.rest_refined())); }
  val refinedTriangles() { return view_of(const_cast<std::vector<int>&>(rig_.refined_triangles())); }
  int cageVertexCount() const { return rig_.cage_vertex_count(); }
  int refinedVertexCount() const { return rig_.refined_vertex_count(); }
  double memoryM() const { return double(rig_.memory_M()); }
  double memoryO() const { return double(rig_.memory_O()); }
  std::string errorMessage() const { return error_; }

 private:
  const double* source_cage(int source) {
    if (source == 0) return rig_.cage().data();
    if (source == 1) return rig_.naive(transforms_.data());
    return cage_in_.data();
  }
  std::vector<Corner> corner_tags() const {
    std::vector<Corner> corners(corner_sharpness_.size());
    for (size_t k = 0; k < corners.size(); ++k) corners[k] = {corner_vertices_[k], corner_sharpness_[k]};
    return corners;
  }
  int fail(const std::string& e) {
    error_ = e;
    return kInvalidInput;
  }
  SubdivisionRig rig_;
  std::vector<double> positions_, crease_sharpness_, handles_, transforms_, cage_in_, per_vertex_;
  std::vector<int> face_sizes_, face_indices_, crease_edges_;
  std::vector<int> corner_vertices_;
  std::vector<double> corner_sharpness_;
  std::vector<double> out_positions_, out_crease_sharpness_, out_corner_sharpness_;
  std::vector<int> out_faces_, out_crease_edges_, out_corner_vertices_;
  std::string error_;
};

}  // namespace
}  // namespace splinekit::skin3d

EMSCRIPTEN_BINDINGS(splinekit_skin3d) {
  using namespace splinekit::skin3d;
  class_<Skin3dRigHandle>("Skin3dRigHandle")
      .constructor<>()
      .function("resize", &Skin3dRigHandle::resize)
      .function("positionsIn", &Skin3dRigHandle::positionsIn)
      .function("faceSizesIn", &Skin3dRigHandle::faceSizesIn)
      .function("faceIndicesIn", &Skin3dRigHandle::faceIndicesIn)
      .function("creaseEdgesIn", &Skin3dRigHandle::creaseEdgesIn)
      .function("creaseSharpnessIn", &Skin3dRigHandle::creaseSharpnessIn)
      .function("resizeCorners", &Skin3dRigHandle::resizeCorners)
      .function("cornerVerticesIn", &Skin3dRigHandle::cornerVerticesIn)
      .function("cornerSharpnessIn", &Skin3dRigHandle::cornerSharpnessIn)
      .function("setup", &Skin3dRigHandle::setup)
      .function("refineCage", &Skin3dRigHandle::refineCage)
      .function("refinedCagePositions", &Skin3dRigHandle::refinedCagePositions)
      .function("refinedCageQuads", &Skin3dRigHandle::refinedCageQuads)
      .function("refinedCageCreaseEdges", &Skin3dRigHandle::refinedCageCreaseEdges)
      .function("refinedCageCreaseSharpness", &Skin3dRigHandle::refinedCageCreaseSharpness)
      .function("refinedCageCornerVertices", &Skin3dRigHandle::refinedCageCornerVertices)
      .function("refinedCageCornerSharpness", &Skin3dRigHandle::refinedCageCornerSharpness)
      .function("handles", &Skin3dRigHandle::handles)
      .function("useShepard", &Skin3dRigHandle::useShepard)
      .function("bbw", &Skin3dRigHandle::bbw)
      .function("bbwLevel", &Skin3dRigHandle::bbwLevel)
      .function("refinedWeights", &Skin3dRigHandle::refinedWeights)
      .function("cageWeights", &Skin3dRigHandle::cageWeights)
      .function("prolongateWeights", &Skin3dRigHandle::prolongateWeights)
      .function("restrictWeights", &Skin3dRigHandle::restrictWeights)
      .function("precompute", &Skin3dRigHandle::precompute)
      .function("transforms", &Skin3dRigHandle::transforms)
      .function("update", &Skin3dRigHandle::update)
      .function("cage", &Skin3dRigHandle::cage)
      .function("naive", &Skin3dRigHandle::naive)
      .function("cageIn", &Skin3dRigHandle::cageIn)
      .function("refine", &Skin3dRigHandle::refine)
      .function("limit", &Skin3dRigHandle::limit)
      .function("target", &Skin3dRigHandle::target)
      .function("error", &Skin3dRigHandle::error)
      .function("perVertexError", &Skin3dRigHandle::perVertexError)
      .function("restRefined", &Skin3dRigHandle::restRefined)
      .function("refinedTriangles", &Skin3dRigHandle::refinedTriangles)
      .function("cageVertexCount", &Skin3dRigHandle::cageVertexCount)
      .function("refinedVertexCount", &Skin3dRigHandle::refinedVertexCount)
      .function("memoryM", &Skin3dRigHandle::memoryM)
      .function("memoryO", &Skin3dRigHandle::memoryO)
      .function("errorMessage", &Skin3dRigHandle::errorMessage);
}
