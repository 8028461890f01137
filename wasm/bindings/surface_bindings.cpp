// Embind glue for surface curves (wasm/core/surface). No algorithm lives here.
//
// Flow (src/surface/mesh.ts drives it): resizeMesh(V, F), write positionsIn() and trianglesIn()
// (file order), build(). Mesh points cross the boundary as (face, u, v) triples of float64 in FILE
// space (face index and barycentrics as the file wrote the face); this glue converts them to and
// from the mesh space of the core. Inputs go in pointsIn() (resizePoints(n) first); results come out
// in pointsOut() (triples), xyzOut() (x, y, z per point) and offsetsOut() (per curve).
#include <emscripten/bind.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/geometry.h"
#include "spline_set_handle.h"
#include "surface/curves.h"
#include "surface/edit.h"

using namespace emscripten;

namespace splinekit {
namespace {

using namespace splinekit::surface;

// What a curve whose control points lie on separate parts of the mesh is told (the tracer stands in
// a path that stays put for each side it cannot find, so the polyline would not be the curve).
constexpr const char* kApart =
    "its control points lie on parts of the mesh that are not connected: a curve cannot cross between them";

class SurfaceMeshHandle {
 public:
  void resizeMesh(int vertices, int faces) {
    positions_in_.assign(3 * size_t(std::max(vertices, 0)), 0.0);
    triangles_in_.assign(3 * size_t(std::max(faces, 0)), 0);
  }
  val positionsIn() { return view_of(positions_in_); }
  val trianglesIn() { return view_of(triangles_in_); }

  // Builds the mesh from positionsIn()/trianglesIn(), and its solver (search graph, landmarks) with
  // `landmarks` landmarks unless `defer_search`: then the solver is built by buildSearch(), or by the
  // first call that needs it (a viewer can show the mesh before the slower search structures exist).
  int build(int landmarks, bool defer_search) {
    TriMesh mesh;
    std::string error;
    auto start = clock::now();
    if (build_mesh(positions_in_.data(), int(positions_in_.size() / 3), triangles_in_.data(),
                   int(triangles_in_.size() / 3), mesh, error) != MeshStatus::kOk)
      return fail(error);
    tracer_.reset();
    solver_.reset();
    mesh_ = std::make_unique<TriMesh>(std::move(mesh));
    build_ms_[0] = elapsed(start);
    build_ms_[1] = build_ms_[2] = 0;
    landmarks_ = std::max(0, landmarks);
    std::vector<double>().swap(positions_in_);
    std::vector<int>().swap(triangles_in_);
    if (!defer_search) buildSearch();
    return kOk;
  }
  // Builds the solver of the mesh if it is not built yet (see build).
  void buildSearch() {
    if (!mesh_ || solver_) return;
    const auto start = clock::now();
    ShortestPathOptions options;
    options.landmarks = landmarks_;
    solver_ = std::make_unique<GeodesicSolver>(*mesh_, options);
    tracer_ = std::make_unique<CurveTracer>(*solver_);
    build_ms_[1] = elapsed(start);
    solver_bytes_ = solver_->bytes();
  }
  bool searchBuilt() const { return solver_ != nullptr; }
  // The landmarks the solver will get, before it is built (build() deferred it); no effect after.
  void setLandmarks(int landmarks) {
    if (!solver_) landmarks_ = std::max(0, landmarks);
  }

  // The solver's coarse guide (surface::CoarseGuide) from a decimation over the file's vertices:
  // resizeGuide(F), write guideIn() (3 file vertex indices per face), buildGuide() (which builds the
  // solver first if build() deferred it). On an error the solver keeps its earlier guide, if any.
  void resizeGuide(int faces) { guide_in_.assign(3 * size_t(std::max(faces, 0)), 0); }
  val guideIn() { return view_of(guide_in_); }
  int buildGuide() {
    if (!mesh_) return fail("no mesh");
    buildSearch();
    const auto start = clock::now();
    std::string error;
    const MeshStatus status = solver_->set_coarse_guide(guide_in_.data(), int(guide_in_.size() / 3), error);
    std::vector<int>().swap(guide_in_);
    if (status != MeshStatus::kOk) return fail(error);
    build_ms_[2] = elapsed(start);
    solver_bytes_ = solver_->bytes();
    return kOk;
  }
  int guideFaces() const {
    return solver_ && solver_->coarse_guide() ? int(solver_->coarse_guide()->coarse().triangles.size()) : 0;
  }

  // The mesh report as {name: count} under the names of surface::report_fields (src/surface/mesh.ts
  // reads them by name); an empty object before a successful build().
  val reportFields() const {
    val out = val::object();
    if (mesh_)
      for (const auto& [name, count] : report_fields(mesh_->report)) out.set(name, count);
    return out;
  }
  // Bytes the mesh and its solver held when built (the solver's search records grow with use).
  double bytes() const { return mesh_ ? double(mesh_bytes(*mesh_) + (solver_ ? solver_bytes_ : 0)) : 0; }
  double scale() const { return mesh_ ? mesh_->scale : 0; }
  int landmarkCount() const { return solver_ ? solver_->landmarks().count() : 0; }
  // The file faces that repeat an earlier face (surface::TriMesh::duplicates), ascending.
  val duplicateFaces() {
    duplicate_faces_.clear();
    if (mesh_)
      for (const auto& [duplicate, first] : mesh_->duplicates) duplicate_faces_.push_back(mesh_->file_face[duplicate]);
    std::sort(duplicate_faces_.begin(), duplicate_faces_.end());
    return view_of(duplicate_faces_);
  }
  // Milliseconds of the last build(): 0 the mesh, 1 its solver (search graph and landmarks), 2 the
  // coarse guide (buildGuide).
  double buildMilliseconds(int part) const { return part >= 0 && part <= 2 ? build_ms_[part] : 0; }

  void resizePoints(int n) { points_in_.assign(3 * size_t(std::max(n, 0)), 0.0); }
  val pointsIn() { return view_of(points_in_); }
  void resizeXY(int n) { xy_in_.assign(2 * size_t(std::max(n, 0)), 0.0); }
  val xyIn() { return view_of(xy_in_); }
  val pointsOut() { return view_of(points_out_); }
  val xyzOut() { return view_of(xyz_out_); }
  val offsetsOut() { return view_of(offsets_out_); }
  double length() const { return length_; }
  double milliseconds() const { return ms_; }
  std::string error() const { return error_; }

  // Shortest path from point 0 to point 1.
  int shortestPath() {
    buildSearch();  // (deferred by build)
    MeshPoint a, b;
    if (!input(0, a) || !input(1, b)) return kInvalidInput;
    const auto start = clock::now();
    GeodesicPath path;
    path_counters_ = {};
    if (!solver_->shortest_path(a, b, path, &path_counters_))
      return fail("the two points lie on parts of the mesh that are not connected");
    ms_ = elapsed(start);
    path_points(*mesh_, path, scratch_);
    length_ = path_length(*mesh_, path);
    output(scratch_);
    return kOk;
  }

  // The points at arc-length fractions t0 and t1 of the shortest path from point 0 to point 1.
  int pathAt(double t0, double t1) {
    buildSearch();  // (deferred by build)
    MeshPoint a, b;
    if (!input(0, a) || !input(1, b)) return kInvalidInput;
    if (!(t0 >= 0 && t0 <= 1 && t1 >= 0 && t1 <= 1)) return fail("path fractions must lie in [0, 1]");
    GeodesicPath path;
    if (!solver_->shortest_path(a, b, path))
      return fail("the two points lie on parts of the mesh that are not connected");
    scratch_.assign({eval_path(*mesh_, path, t0), eval_path(*mesh_, path, t1)});
    output(scratch_);
    return kOk;
  }

  // Straightest geodesic from point 0 in direction (dx, dy, dz) (projected to the tangent plane).
  int straightest(double dx, double dy, double dz, double length) {
    buildSearch();  // (deferred by build)
    MeshPoint a;
    if (!input(0, a)) return kInvalidInput;
    if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(dz) || !std::isfinite(length) || length < 0)
      return fail("the direction and length must be finite numbers (length >= 0)");
    const Vec3 n = face_normal(*mesh_, a.face);
    Vec3 d(dx, dy, dz);
    d -= n * d.dot(n);
    if (d.norm() == 0) return fail("the direction is perpendicular to the surface");
    StraightestGeodesic out;
    straightest_geodesic(*mesh_, a, {a.face, d.normalized()}, length, out);
    length_ = out.length;
    output(out.points);
    return kOk;
  }

  // Traces `curves` cubic curves whose control points are in pointsIn() (4 per curve). Per curve
  // timings in milliseconds come out through curveMilliseconds(i).
  int trace(int curves, int scheme, int levels, double adaptive_degrees) {
    buildSearch();  // (deferred by build)
    if (curves < 0 || 4 * size_t(curves) * 3 > points_in_.size()) return fail("expected 4 control points per curve");
    TraceOptions options;
    if (!set_options(scheme, levels, adaptive_degrees, options)) return kInvalidInput;
    std::vector<ControlPolygon> polygons(curves);
    for (int c = 0; c < curves; ++c)
      for (int i = 0; i < 4; ++i)
        if (!input(4 * c + i, polygons[c][i])) return fail("curve " + std::to_string(c) + ": " + error_);
    points_out_.clear();
    xyz_out_.clear();
    offsets_out_.assign(1, 0);
    curve_ms_.assign(curves, 0.0);
    curve_counters_.assign(curves, TraceStats{});
    for (int c = 0; c < curves; ++c) {
      const auto start = clock::now();
      tracer_->stats = {};
      tracer_->trace(polygons[c], options, scratch_);
      if (tracer_->stats.unreachable_paths > 0) return fail("curve " + std::to_string(c) + ": " + kApart);
      curve_ms_[c] = elapsed(start);
      curve_counters_[c] = tracer_->stats;
      append(scratch_);
      offsets_out_.push_back(int(points_out_.size() / 3));
    }
    return kOk;
  }
  double curveMilliseconds(int c) const { return c >= 0 && c < int(curve_ms_.size()) ? curve_ms_[c] : 0; }
  // The work counters of curve c of the last trace() (an empty object for another c), and of the last
  // shortestPath(): the cost of a curve or path as the benchmarks report it.
  val curveCounters(int c) const {
    if (c < 0 || c >= int(curve_counters_.size())) return val::object();
    const TraceStats& t = curve_counters_[c];
    val out = counters(t.paths);
    out.set("searchedPaths", t.shortest_paths);
    out.set("seededPaths", t.seeded_paths);
    return out;
  }
  val pathCounters() const { return counters(path_counters_); }

  // Point at t of the curve in pointsIn()[0..4).
  int evalCurve(double t, int scheme, int levels, double adaptive_degrees) {
    buildSearch();  // (deferred by build)
    TraceOptions options;
    ControlPolygon polygon;
    if (!set_options(scheme, levels, adaptive_degrees, options) || !polygon_input(polygon)) return kInvalidInput;
    if (!std::isfinite(t)) return fail("t must be a finite number");
    tracer_->stats = {};
    scratch_.assign(1, tracer_->eval(polygon, t, options));
    if (tracer_->stats.unreachable_paths > 0) return fail(kApart);
    output(scratch_);
    return kOk;
  }

  // Point insertion: 7 control points (P0, ., ., Pt, ., ., P3) out.
  int splitCurve(double t, int scheme, int levels, double adaptive_degrees) {
    buildSearch();  // (deferred by build)
    TraceOptions options;
    ControlPolygon polygon, left, right;
    if (!set_options(scheme, levels, adaptive_degrees, options) || !polygon_input(polygon)) return kInvalidInput;
    if (!(t > 0 && t < 1)) return fail("the split parameter must lie strictly between 0 and 1");
    tracer_->stats = {};
    tracer_->split(polygon, t, options, left, right);
    if (tracer_->stats.unreachable_paths > 0) return fail(kApart);
    scratch_.assign(left.begin(), left.end());
    scratch_.insert(scratch_.end(), right.begin() + 1, right.end());
    output(scratch_);
    return kOk;
  }

  // ---- Editing: the spline's control points are pointsIn()[0..count); results in pointsOut() ----
  int moveAnchor(int count, int index, double f, double u, double v) {
    buildSearch();  // (deferred by build)
    MeshPoint to;
    if (!spline_input(count, index) || !point(f, u, v, to)) return kInvalidInput;
    move_anchor(*solver_, spline_, index, to);
    output(spline_);
    return kOk;
  }
  int moveHandle(int count, int index, double f, double u, double v, bool smooth) {
    buildSearch();  // (deferred by build)
    MeshPoint to;
    if (!spline_input(count, index) || !point(f, u, v, to)) return kInvalidInput;
    move_handle(*solver_, spline_, index, to, smooth);
    output(spline_);
    return kOk;
  }
  int smoothAnchor(int count, int index) {
    buildSearch();  // (deferred by build)
    if (!spline_input(count, index)) return kInvalidInput;
    make_smooth(*solver_, spline_, index);
    output(spline_);
    return kOk;
  }
  int rotateScale(int count, double f, double u, double v, double angle, double scale) {
    buildSearch();  // (deferred by build)
    MeshPoint c;
    if (!spline_input(count, 0) || !point(f, u, v, c)) return kInvalidInput;
    if (!std::isfinite(angle) || !std::isfinite(scale) || scale < 0)
      return fail("angle and scale must be finite (scale >= 0)");
    rotate_scale(*solver_, spline_, c, angle, scale);
    output(spline_);
    return kOk;
  }
  int translateSpline(int count, double f0, double u0, double v0, double f1, double u1, double v1) {
    buildSearch();  // (deferred by build)
    MeshPoint from, to;
    if (!spline_input(count, 0) || !point(f0, u0, v0, from) || !point(f1, u1, v1, to)) return kInvalidInput;
    translate(*solver_, spline_, from, to);
    output(spline_);
    return kOk;
  }
  // Maps xyIn() (2D, y down) about the point (f, u, v).
  int mapPoints(double f, double u, double v, double ux, double uy, double uz, double rotation, double scale) {
    buildSearch();  // (deferred by build)
    MeshPoint c;
    if (!point(f, u, v, c)) return kInvalidInput;
    if (!std::isfinite(rotation) || !std::isfinite(scale) || !(scale > 0))
      return fail("rotation and scale must be finite (scale > 0)");
    for (double x : xy_in_)
      if (!std::isfinite(x)) return fail("the drawing has a non-finite coordinate");
    map_points(*mesh_, c, Vec3(ux, uy, uz), rotation, scale, xy_in_.data(), int(xy_in_.size() / 2), scratch_);
    output(scratch_);
    return kOk;
  }

 private:
  using clock = std::chrono::steady_clock;
  static double elapsed(clock::time_point start) {
    return std::chrono::duration<double, std::milli>(clock::now() - start).count();
  }
  static val counters(const PathStats& s) {
    val out = val::object();
    out.set("searches", s.searches);
    out.set("visitedNodes", s.visited_nodes);
    out.set("stripFaces", s.strip_faces);
    out.set("passes", s.passes);
    out.set("flips", s.accepted_flips);
    out.set("frozenVertices", s.frozen_vertices);
    out.set("chordsTried", s.chords_tried);
    out.set("chords", s.chords_kept);
    out.set("walkedFaces", s.walked_faces);
    out.set("passFaces", s.pass_faces);
    out.set("windows", s.windows);
    out.set("guided", s.guided);
    return out;
  }

  int fail(std::string message) {
    error_ = std::move(message);
    return kInvalidInput;
  }

  bool point(double f, double u, double v, MeshPoint& out) {
    if (!mesh_) return fail("no mesh has been built"), false;
    const int faces = int(mesh_->triangles.size());
    if (!(f >= 0 && f < faces) || f != std::floor(f)) {
      fail("face " + std::to_string(f) + " is not a face of the mesh (it has " + std::to_string(faces) + ")");
      return false;
    }
    constexpr double eps = 1e-9;
    if (!std::isfinite(u) || !std::isfinite(v) || u < -eps || v < -eps || u + v > 1 + eps) {
      fail("barycentric coordinates (" + std::to_string(u) + ", " + std::to_string(v) + ") lie outside face " +
           std::to_string(int(f)));
      return false;
    }
    u = std::clamp(u, 0.0, 1.0);
    v = std::clamp(v, 0.0, 1.0 - u);
    out = to_mesh_point(*mesh_, {int(f), Vec2(u, v)});
    return true;
  }
  bool input(int i, MeshPoint& out) {
    if (3 * size_t(i) + 2 >= points_in_.size()) return fail("missing point " + std::to_string(i)), false;
    return point(points_in_[3 * i], points_in_[3 * i + 1], points_in_[3 * i + 2], out);
  }
  bool polygon_input(ControlPolygon& polygon) {
    for (int i = 0; i < 4; ++i)
      if (!input(i, polygon[i])) return false;
    return true;
  }
  bool spline_input(int count, int index) {
    if (count < 1 || 3 * size_t(count) > points_in_.size()) return fail("the spline has no control points"), false;
    if (index < 0 || index >= count) return fail("control point " + std::to_string(index) + " does not exist"), false;
    spline_.resize(count);
    for (int i = 0; i < count; ++i)
      if (!input(i, spline_[i])) return false;
    return true;
  }
  bool set_options(int scheme, int levels, double adaptive_degrees, TraceOptions& options) {
    if (!mesh_) return fail("no mesh has been built"), false;
    if (scheme != 0 && scheme != 1) return fail("the scheme must be OLR or RDC"), false;
    options.scheme = scheme == 0 ? Scheme::kOLR : Scheme::kRDC;
    if (adaptive_degrees > 0) {
      if (!(adaptive_degrees < 180)) return fail("the adaptive angle must lie between 0 and 180 degrees"), false;
      options.adaptive = true;
      options.angle = adaptive_degrees * kPi / 180;
    } else {
      if (levels > 12) return fail("levels must lie between 0 and 12"), false;
      options.levels = levels;  // negative: default_levels(scheme)
    }
    return true;
  }
  void output(const std::vector<MeshPoint>& points) {
    points_out_.clear();
    xyz_out_.clear();
    append(points);
  }
  void append(const std::vector<MeshPoint>& points) {
    for (const MeshPoint& p : points) {
      const MeshPoint file = to_file_point(*mesh_, p);
      points_out_.insert(points_out_.end(), {double(file.face), file.uv.x(), file.uv.y()});
      const Vec3 x = eval_position(*mesh_, p);
      xyz_out_.insert(xyz_out_.end(), {x.x(), x.y(), x.z()});
    }
  }

  std::unique_ptr<TriMesh> mesh_;
  std::unique_ptr<GeodesicSolver> solver_;
  int landmarks_ = 0;
  size_t solver_bytes_ = 0;
  std::unique_ptr<CurveTracer> tracer_;
  std::vector<double> positions_in_;
  std::vector<int> triangles_in_;
  std::vector<int> guide_in_;
  std::vector<double> points_in_, xy_in_, points_out_, xyz_out_, curve_ms_;
  std::vector<int> offsets_out_, duplicate_faces_;
  std::vector<MeshPoint> scratch_, spline_;
  std::vector<TraceStats> curve_counters_;
  PathStats path_counters_;
  double length_ = 0, ms_ = 0, build_ms_[3] = {0, 0, 0};
  std::string error_;
};

}  // namespace
}  // namespace splinekit

EMSCRIPTEN_BINDINGS(splinekit_surface) {
  using namespace splinekit;
  class_<SurfaceMeshHandle>("SurfaceMeshHandle")
      .constructor<>()
      .function("resizeMesh", &SurfaceMeshHandle::resizeMesh)
      .function("positionsIn", &SurfaceMeshHandle::positionsIn)
      .function("trianglesIn", &SurfaceMeshHandle::trianglesIn)
      .function("build", &SurfaceMeshHandle::build)
      .function("reportFields", &SurfaceMeshHandle::reportFields)
      .function("bytes", &SurfaceMeshHandle::bytes)
      .function("scale", &SurfaceMeshHandle::scale)
      .function("landmarkCount", &SurfaceMeshHandle::landmarkCount)
      .function("duplicateFaces", &SurfaceMeshHandle::duplicateFaces)
      .function("buildSearch", &SurfaceMeshHandle::buildSearch)
      .function("searchBuilt", &SurfaceMeshHandle::searchBuilt)
      .function("setLandmarks", &SurfaceMeshHandle::setLandmarks)
      .function("resizeGuide", &SurfaceMeshHandle::resizeGuide)
      .function("guideIn", &SurfaceMeshHandle::guideIn)
      .function("buildGuide", &SurfaceMeshHandle::buildGuide)
      .function("guideFaces", &SurfaceMeshHandle::guideFaces)
      .function("buildMilliseconds", &SurfaceMeshHandle::buildMilliseconds)
      .function("resizePoints", &SurfaceMeshHandle::resizePoints)
      .function("pointsIn", &SurfaceMeshHandle::pointsIn)
      .function("resizeXY", &SurfaceMeshHandle::resizeXY)
      .function("xyIn", &SurfaceMeshHandle::xyIn)
      .function("pointsOut", &SurfaceMeshHandle::pointsOut)
      .function("xyzOut", &SurfaceMeshHandle::xyzOut)
      .function("offsetsOut", &SurfaceMeshHandle::offsetsOut)
      .function("length", &SurfaceMeshHandle::length)
      .function("milliseconds", &SurfaceMeshHandle::milliseconds)
      .function("curveMilliseconds", &SurfaceMeshHandle::curveMilliseconds)
      .function("curveCounters", &SurfaceMeshHandle::curveCounters)
      .function("pathCounters", &SurfaceMeshHandle::pathCounters)
      .function("error", &SurfaceMeshHandle::error)
      .function("shortestPath", &SurfaceMeshHandle::shortestPath)
      .function("straightest", &SurfaceMeshHandle::straightest)
      .function("pathAt", &SurfaceMeshHandle::pathAt)
      .function("trace", &SurfaceMeshHandle::trace)
      .function("evalCurve", &SurfaceMeshHandle::evalCurve)
      .function("splitCurve", &SurfaceMeshHandle::splitCurve)
      .function("moveAnchor", &SurfaceMeshHandle::moveAnchor)
      .function("moveHandle", &SurfaceMeshHandle::moveHandle)
      .function("smoothAnchor", &SurfaceMeshHandle::smoothAnchor)
      .function("rotateScale", &SurfaceMeshHandle::rotateScale)
      .function("translateSpline", &SurfaceMeshHandle::translateSpline)
      .function("mapPoints", &SurfaceMeshHandle::mapPoints);
}
