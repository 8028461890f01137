// One side of `npm run bench:ab`: the surface core of one source tree, compiled with its namespace
// renamed (-Dsplinekit=splinekit_ab_<SIDE>) so that two trees link into one module. Reads the
// mesh the driver wrote (file arrays) and the benchmark's random control points (file space), and
// traces curve i on request: OLR, 5 levels, as `npm run bench` does.
#include "surface/curves.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#define SPLINEKIT_AB_CAT2(a, b) a##b
#define SPLINEKIT_AB_CAT(a, b) SPLINEKIT_AB_CAT2(a, b)
#define SPLINEKIT_AB(name) SPLINEKIT_AB_CAT(name, SPLINEKIT_AB_SIDE)

using namespace splinekit::surface;

namespace {
struct Side {
  TriMesh mesh;
  std::unique_ptr<GeodesicSolver> solver;
  std::unique_ptr<CurveTracer> tracer;
  std::vector<MeshPoint> points;  // mesh space, 4 per curve
  std::vector<MeshPoint> polyline;
};

template <class T>
bool read(FILE* in, std::vector<T>& out, size_t n) {
  out.resize(n);
  return fread(out.data(), sizeof(T), n, in) == n;
}
}  // namespace

// mesh: int32 #vertices, #faces, then float64 positions (3 per vertex), int32 triangles (3 per
// face); points: int32 #points, then per point int32 face, float64 u, v; guide (optional): int32
// landmarks, int32 #faces (0: no guide), then int32 mesh vertex indices (3 per face), the landmarks
// and coarse guide the library gives the mesh (src/surface/mesh.ts).
extern "C" void* SPLINEKIT_AB(ab_init_)(const char* mesh_path, const char* points_path, const char* guide_path) {
  auto side = std::make_unique<Side>();
  FILE* in = fopen(mesh_path, "rb");
  int counts[2];
  std::vector<double> positions;
  std::vector<int> triangles;
  if (!in || fread(counts, sizeof(int), 2, in) != 2 || !read(in, positions, 3 * size_t(counts[0])) ||
      !read(in, triangles, 3 * size_t(counts[1]))) {
    fprintf(stderr, "cannot read %s\n", mesh_path);
    return nullptr;
  }
  fclose(in);
  std::string error;
  if (build_mesh(positions.data(), counts[0], triangles.data(), counts[1], side->mesh, error) != MeshStatus::kOk) {
    fprintf(stderr, "%s\n", error.c_str());
    return nullptr;
  }
  std::vector<int> guide;
  ShortestPathOptions options;
  if (guide_path) {
    in = fopen(guide_path, "rb");
    int header[2];  // landmarks, #faces
    if (!in || fread(header, sizeof(int), 2, in) != 2 || !read(in, guide, 3 * size_t(header[1]))) {
      fprintf(stderr, "cannot read %s\n", guide_path);
      return nullptr;
    }
    fclose(in);
    options.landmarks = header[0];
  }
  side->solver = std::make_unique<GeodesicSolver>(side->mesh, options);
  if (!guide.empty() &&
      side->solver->set_coarse_guide(guide.data(), static_cast<int>(guide.size() / 3), error) != MeshStatus::kOk) {
    fprintf(stderr, "guide: %s\n", error.c_str());
    return nullptr;
  }
  side->tracer = std::make_unique<CurveTracer>(*side->solver);
  in = fopen(points_path, "rb");
  int n = 0;
  if (!in || fread(&n, sizeof(int), 1, in) != 1) return nullptr;
  for (int i = 0; i < n; ++i) {
    int face;
    double uv[2];
    if (fread(&face, sizeof(int), 1, in) != 1 || fread(uv, sizeof(double), 2, in) != 2) return nullptr;
    // (Eigen's own name: older trees call it surface::Vec2, newer ones splinekit::Vec2)
    side->points.push_back(to_mesh_point(side->mesh, MeshPoint{face, Eigen::Vector2d(uv[0], uv[1])}));
  }
  fclose(in);
  return side.release();
}

extern "C" int SPLINEKIT_AB(ab_curves_)(void* p) { return static_cast<int>(static_cast<Side*>(p)->points.size() / 4); }

// Milliseconds to trace curve i; its length (in mesh diagonals) in *length.
extern "C" double SPLINEKIT_AB(ab_trace_)(void* p, int i, double* length) {
  Side& side = *static_cast<Side*>(p);
  const ControlPolygon polygon = {side.points[4 * i], side.points[4 * i + 1], side.points[4 * i + 2],
                                  side.points[4 * i + 3]};
  const auto start = std::chrono::steady_clock::now();
  side.tracer->trace(polygon, TraceOptions{}, side.polyline);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  double sum = 0;
  for (size_t k = 1; k < side.polyline.size(); ++k)
    sum += (eval_position(side.mesh, side.polyline[k]) - eval_position(side.mesh, side.polyline[k - 1])).norm();
  *length = sum / side.mesh.scale;
  return ms;
}
