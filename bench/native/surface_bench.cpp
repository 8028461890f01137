// Native side of the surface benchmarks (bench/surface.mjs runs it once per mesh): quality and speed
// of locally shortest paths (GeodesicSolver::shortest_path) against the exact polyhedral geodesic
// distance (tests/native/reference/exact_geodesic.h, MMP windows), for the default refined search
// graph and for the paper's plain dual graph (SearchGraph::kDual), plus the memory and precompute
// time of the mesh structures.
//
// usage: surface_bench <mesh.obj|mesh.ply> <sources> <targets per source> [seed]
// Prints one JSON object on stdout.
//
// Protocol: `sources` random mesh vertices; for each, the exact distance to every vertex (one MMP
// run), then `targets` random other vertices, each reached by one shortest path per search graph.
// A path's ratio is its length over the exact distance: >= 1 up to rounding (a path on the surface
// cannot be shorter than the geodesic distance), 1 when the path is globally shortest.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "../../tests/native/reference/exact_geodesic.h"
#include "../../tests/native/surface/test_meshes.h"
#include "surface/geodesic.h"

using namespace splinekit::surface;
using Clock = std::chrono::steady_clock;

static double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

static double percentile(std::vector<double> xs, double p) {
  if (xs.empty()) return 0;
  std::sort(xs.begin(), xs.end());
  const size_t i = std::min(xs.size() - 1, static_cast<size_t>(std::floor(p * (xs.size() - 1) + 0.5)));
  return xs[i];
}

struct Quality {
  int paths = 0;
  int within = 0;    // ratio <= 1.005
  int shorter = 0;   // length < exact * (1 - 1e-9)
  int failed = 0;    // shortest_path returned false for a reachable target
  double worst = 1;  // largest ratio
  double sum_ratio = 0;
  std::vector<double> ms;
  std::vector<double> visited;

  void add(double length, double exact, double t, int nodes) {
    ++paths;
    const double r = length / exact;
    within += r <= 1.005;
    shorter += length < exact * (1 - 1e-9);
    worst = std::max(worst, r);
    sum_ratio += r;
    ms.push_back(t);
    visited.push_back(nodes);
  }

  std::string json() const {
    double total = 0;
    for (double t : ms) total += t;
    char buf[512];
    std::snprintf(
        buf, sizeof buf,
        "{\"paths\":%d,\"within_0_5pct\":%d,\"within_pct\":%.2f,\"shorter\":%d,\"failed\":%d,\"worst_ratio\":%.6f,"
        "\"mean_ratio\":%.6f,\"mean_ms\":%.4f,\"median_ms\":%.4f,\"p99_ms\":%.4f,\"median_visited_nodes\":%.0f}",
        paths, within, paths ? 100.0 * within / paths : 0.0, shorter, failed, worst, paths ? sum_ratio / paths : 0.0,
        paths ? total / paths : 0.0, percentile(ms, 0.5), percentile(ms, 0.99), percentile(visited, 0.5));
    return buf;
  }
};

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: surface_bench <mesh.obj|mesh.ply> <sources> <targets per source> [seed]\n");
    return 2;
  }
  const std::string file = argv[1];
  const int sources = std::atoi(argv[2]), targets = std::atoi(argv[3]);
  const unsigned seed = argc > 4 ? static_cast<unsigned>(std::atoi(argv[4])) : 1u;

  auto t0 = Clock::now();
  const splinekit::surface::testing::Arrays arrays = splinekit::surface::testing::read_mesh(file);
  const double read_ms = ms_since(t0);

  // Precompute: build_mesh (welding, orientation, adjacency) and the solver (search graph), median of 3.
  std::vector<double> build_times, solver_times;
  TriMesh mesh;
  for (int rep = 0; rep < 3; ++rep) {
    TriMesh m;
    std::string error;
    t0 = Clock::now();
    if (build_mesh(arrays.positions.data(), arrays.vertices(), arrays.triangles.data(), arrays.faces(), m, error) !=
        MeshStatus::kOk) {
      std::fprintf(stderr, "surface_bench: %s: %s\n", file.c_str(), error.c_str());
      return 1;
    }
    build_times.push_back(ms_since(t0));
    t0 = Clock::now();
    GeodesicSolver s(m);
    solver_times.push_back(ms_since(t0));
    if (rep == 2) mesh = std::move(m);
  }
  GeodesicSolver solver(mesh);
  const size_t mb = mesh_bytes(mesh), sb = solver.bytes();
  const int nf = static_cast<int>(mesh.triangles.size()), nv = static_cast<int>(mesh.positions.size());

  // The exact reference works on the repaired (mesh-space) surface the solver sees; faces that
  // repeat a vertex have no area and are left out.
  std::vector<double> P(3 * size_t(nv));
  for (int v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) P[3 * size_t(v) + k] = mesh.positions[v][k];
  std::vector<int> T;
  T.reserve(3 * size_t(nf));
  for (const auto& t : mesh.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) T.insert(T.end(), {t[0], t[1], t[2]});
  t0 = Clock::now();
  splinekit::reference::ExactGeodesic exact(P.data(), nv, T.data(), static_cast<int>(T.size() / 3));
  const double exact_build_ms = ms_since(t0);

  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> vertex(0, nv - 1);
  Quality refined, dual;
  std::vector<double> exact_ms;
  int unreachable = 0;
  GeodesicPath path;
  for (int s = 0; s < sources; ++s) {
    const int src = vertex(rng);
    t0 = Clock::now();
    const std::vector<double> d = exact.distances(src);
    exact_ms.push_back(ms_since(t0));
    for (int k = 0; k < targets; ++k) {
      int dst = vertex(rng);
      while (dst == src || d[dst] == 0) dst = vertex(rng);
      if (!std::isfinite(d[dst])) {
        ++unreachable;
        continue;
      }
      const MeshPoint a = vertex_point(mesh, src), b = vertex_point(mesh, dst);
      for (auto [graph, q] :
           {std::pair<SearchGraph, Quality*>{SearchGraph::kRefined, &refined}, {SearchGraph::kDual, &dual}}) {
        PathStats stats;
        t0 = Clock::now();
        const bool ok = solver.shortest_path(a, b, path, &stats, graph);
        const double t = ms_since(t0);
        if (!ok) {
          ++q->failed;
          continue;
        }
        q->add(path_length(mesh, path), d[dst], t, stats.visited_nodes);
      }
    }
  }
  double exact_total = 0;
  for (double t : exact_ms) exact_total += t;
  const size_t sb_after = solver.bytes();  // the search scratch grows with the searches
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_mb = usage.ru_maxrss / 1024.0;  // kilobytes on Linux

  std::printf(
      "{\"file_vertices\":%d,\"file_faces\":%d,\"vertices\":%d,\"triangles\":%d,\"read_ms\":%.1f,"
      "\"build_mesh_ms\":%.2f,\"solver_ms\":%.2f,\"precompute_ms\":%.2f,"
      "\"graph_nodes\":%d,\"graph_edges\":%d,\"mesh_bytes\":%zu,\"solver_bytes\":%zu,\"bytes_per_triangle\":%.2f,"
      "\"bytes_per_triangle_after_paths\":%.2f,"
      "\"sources\":%d,\"targets_per_source\":%d,\"seed\":%u,\"unreachable\":%d,"
      "\"exact_build_ms\":%.1f,\"exact_ms_per_source\":%.1f,\"peak_rss_mb\":%.0f,"
      "\"refined\":%s,\"dual\":%s}\n",
      arrays.vertices(), arrays.faces(), nv, nf, read_ms, percentile(build_times, 0.5), percentile(solver_times, 0.5),
      percentile(build_times, 0.5) + percentile(solver_times, 0.5), solver.graph().nodes(), solver.graph().edges, mb,
      sb, double(mb + sb) / nf, double(mb + sb_after) / nf, sources, targets, seed, unreachable, exact_build_ms,
      sources ? exact_total / sources : 0.0, peak_mb, refined.json().c_str(), dual.json().c_str());
  return 0;
}
