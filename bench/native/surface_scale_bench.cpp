// Native side of the "surface at scale" benchmark (bench/surface-scale.mjs runs it):
//
//   surface_scale_bench shape coil|knot|folded|uvsphere|noisy|noisy-cube|small-noisy-coil|small-noisy-folded <out.obj>
//                             [<in mesh> for noisy]
//       writes a generated mesh (tests/native/surface/test_meshes.h: the same shapes the tests use,
//       at benchmark size): the coil (8 turns, tube radius 0.12, pitch 0.3, 4000 x 48 quads,
//       384k triangles), a tube along a torus knot (3000 x 24 quads, 144k triangles, faces six times
//       longer around than along), a body with two limbs folded against it (3000 x 64 quads, 384k triangles,
//       and 150 specks of debris), a UV sphere of 2000 x 150 quads (596k triangles, faces 7:1 at the
//       equator),
//       or <in mesh> with normal noise of +-0.3 mean edge lengths (seed 3).
//   surface_scale_bench exact <mesh>   (pairs "a b" of file vertex indices on stdin)
//       prints {"distances":[...]}: the exact polyhedral geodesic distance of every pair
//       (tests/native/reference/exact_geodesic.h, MMP windows; one run per distinct source) on the
//       file's own vertices and triangles, and {"ms_per_source":..}.
//   surface_scale_bench search <mesh> <pairs> <seed>
//       phase (i) alone, with and without landmarks, on random face pairs: nodes expanded and time
//       per search for the kDual and kRefined graphs, and the landmark precompute.
//   surface_scale_bench steiner <mesh> <sources> <targets> <seed>
//       shortest paths between random vertices (sources x targets) with 1 to 4 search-graph nodes per
//       edge (ShortestPathOptions::steiner) against the exact distance (MMP): the share within 0.5%,
//       the worst ratio and the total time per count, as {"steiner":[...]} (BENCHMARKS.md, "Why
//       these defaults", was measured with it at 10 x 50).
//   surface_scale_bench curves <mesh> <polygons> <seed> [lengths] [<guide.obj>]
//       random whole-surface curves (4 control points uniform over the area), OLR 5 levels, as the
//       wasm benchmark traces them: per-curve ms (median, p90, p99, max; this thread's CPU time, so
//       that other work on the machine does not inflate it) and work counters (median,
//       p99); with `lengths`, every curve's polyline length too (to compare two builds' curves);
//       with <guide.obj> (faces over the mesh's vertices: a decimation such as SurfaceMesh's, written
//       with all of the mesh's vertices), the solver's coarse guide (GeodesicSolver::set_coarse_guide).
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "../../tests/native/reference/exact_geodesic.h"
#include "../../tests/native/surface/test_meshes.h"
#include "surface/curves.h"
#include "surface/geodesic.h"

using namespace splinekit::surface;
using splinekit::surface::testing::Arrays;
using Clock = std::chrono::steady_clock;
using splinekit::Vec3;

static double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU time of this thread (ms): per-curve times that other work on the machine does not inflate.
static double thread_ms() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec;
}

static int write_obj(const Arrays& a, const std::string& path) {
  FILE* out = std::fopen(path.c_str(), "w");
  if (!out) {
    std::fprintf(stderr, "surface_scale_bench: cannot write %s\n", path.c_str());
    return 1;
  }
  for (int v = 0; v < a.vertices(); ++v)
    std::fprintf(out, "v %.17g %.17g %.17g\n", a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]);
  for (int f = 0; f < a.faces(); ++f)
    std::fprintf(out, "f %d %d %d\n", a.triangles[3 * f] + 1, a.triangles[3 * f + 1] + 1, a.triangles[3 * f + 2] + 1);
  std::fclose(out);
  return 0;
}

static int shape(int argc, char** argv) {
  const std::string kind = argv[2], out = argv[3];
  if (kind == "coil") return write_obj(testing::coil(4000, 48), out);
  if (kind == "knot") return write_obj(testing::knot_tube(3000, 24), out);
  // With specks of debris, as a scan of a folded creature has (the Stanford dragon: 150).
  if (kind == "folded") return write_obj(testing::with_debris(testing::folded_body(3000, 64), 150, 3, 0.002), out);
  // A modeler's UV sphere: 2000 x 150 quads, faces 7:1 at the equator, fans of 2000 at the poles.
  if (kind == "uvsphere") return write_obj(testing::uv_sphere(2000, 150), out);
  if (kind == "noisy" && argc > 4) return write_obj(testing::noisy(testing::read_mesh(argv[4]), 0.3, 3), out);
  // Small noisy shapes for accuracy checks against the exact distance (`steiner`), which is too slow
  // on the benchmark's 384k-triangle ones.
  if (kind == "noisy-cube") return write_obj(testing::noisy(testing::cube(24), 0.4, 5), out);
  if (kind == "small-noisy-coil") return write_obj(testing::noisy(testing::coil(800, 16), 0.3, 5), out);
  if (kind == "small-noisy-folded") return write_obj(testing::noisy(testing::folded_body(600, 24), 0.3, 5), out);
  std::fprintf(stderr, "surface_scale_bench: unknown shape %s\n", kind.c_str());
  return 2;
}

static int exact(const std::string& file) {
  const Arrays a = testing::read_mesh(file);
  std::vector<std::pair<int, int>> pairs;
  for (int s, t; std::cin >> s >> t;) pairs.push_back({s, t});
  splinekit::reference::ExactGeodesic solver(a.positions.data(), a.vertices(), a.triangles.data(), a.faces());
  std::map<int, std::vector<double>> from;
  double ms = 0;
  for (const auto& [s, t] : pairs) {
    if (from.count(s)) continue;
    const auto t0 = Clock::now();
    from[s] = solver.distances(s);
    ms += ms_since(t0);
  }
  std::printf("{\"ms_per_source\":%.1f,\"distances\":[", from.empty() ? 0.0 : ms / from.size());
  for (size_t i = 0; i < pairs.size(); ++i) std::printf("%s%.17g", i ? "," : "", from[pairs[i].first][pairs[i].second]);
  std::printf("]}\n");
  return 0;
}

static int search(const std::string& file, int pairs, unsigned seed) {
  const TriMesh mesh = testing::build(testing::read_mesh(file));
  const int nf = static_cast<int>(mesh.triangles.size());
  ShortestPathOptions none;
  none.landmarks = 0;
  auto t0 = Clock::now();
  GeodesicSolver plain(mesh, none);
  const double plain_ms = ms_since(t0);
  t0 = Clock::now();
  GeodesicSolver alt(mesh);
  const double alt_ms = ms_since(t0);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> face(0, nf - 1);
  std::vector<int> strip;
  std::printf("{\"triangles\":%d,\"landmarks\":%d,\"solver_ms\":%.1f,\"solver_with_landmarks_ms\":%.1f,\"graphs\":{",
              nf, alt.landmarks().count(), plain_ms, alt_ms);
  bool first = true;
  for (SearchGraph graph : {SearchGraph::kDual, SearchGraph::kRefined}) {
    std::vector<double> nodes[2], ms[2];
    std::mt19937 local(rng());
    for (int i = 0; i < pairs; ++i) {
      const MeshPoint a{face(local), splinekit::Vec2(1.0 / 3, 1.0 / 3)},
          b{face(local), splinekit::Vec2(1.0 / 3, 1.0 / 3)};
      for (int k = 0; k < 2; ++k) {
        PathStats stats;
        t0 = Clock::now();
        (k ? alt : plain).initial_strip(a, b, strip, &stats, graph);
        ms[k].push_back(ms_since(t0));
        nodes[k].push_back(stats.visited_nodes);
      }
    }
    auto median = [](std::vector<double> x) {
      std::sort(x.begin(), x.end());
      return x.empty() ? 0.0 : x[x.size() / 2];
    };
    auto mean = [](const std::vector<double>& x) {
      double s = 0;
      for (double v : x) s += v;
      return x.empty() ? 0.0 : s / x.size();
    };
    std::printf(
        "%s\"%s\":{\"pairs\":%d,\"without\":{\"median_nodes\":%.0f,\"mean_nodes\":%.0f,\"median_ms\":%.3f,\"mean_ms\":%"
        ".3f},"
        "\"with\":{\"median_nodes\":%.0f,\"mean_nodes\":%.0f,\"median_ms\":%.3f,\"mean_ms\":%.3f}}",
        first ? "" : ",", graph == SearchGraph::kDual ? "dual" : "refined", pairs, median(nodes[0]), mean(nodes[0]),
        median(ms[0]), mean(ms[0]), median(nodes[1]), mean(nodes[1]), median(ms[1]), mean(ms[1]));
    first = false;
  }
  std::printf("}}\n");
  return 0;
}

static int steiner(const std::string& file, int sources, int targets, unsigned seed) {
  const TriMesh mesh = testing::build(testing::read_mesh(file));
  splinekit::reference::ExactGeodesic exact = testing::exact_geodesic(mesh);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(mesh.positions.size()) - 1);
  struct Pair {
    int a, b;
    double exact;
  };
  std::vector<Pair> pairs;
  for (int s = 0; s < sources; ++s) {
    const int a = vertex(rng);
    const std::vector<double> d = exact.distances(a);
    for (int t = 0; t < targets; ++t) {
      const int b = vertex(rng);
      if (b != a && d[b] > 0 && std::isfinite(d[b])) pairs.push_back({a, b, d[b]});
    }
  }
  std::printf("{\"triangles\":%zu,\"pairs\":%zu,\"steiner\":[", mesh.triangles.size(), pairs.size());
  for (int count = 1; count <= 4; ++count) {
    ShortestPathOptions options;
    options.steiner = count;
    GeodesicSolver solver(mesh, options);
    int within = 0, shorter = 0;
    double worst = 1, ms = 0;
    GeodesicPath path;
    for (const Pair& p : pairs) {
      const double t0 = thread_ms();
      solver.shortest_path(vertex_point(mesh, p.a), vertex_point(mesh, p.b), path);
      ms += thread_ms() - t0;
      const double ratio = path_length(mesh, path) / p.exact;
      within += ratio <= 1.005, shorter += ratio < 1 - 1e-9, worst = std::max(worst, ratio);
    }
    std::printf("%s{\"steiner\":%d,\"within_pct\":%.2f,\"shorter\":%d,\"worst_ratio\":%.5f,\"total_ms\":%.1f}",
                count > 1 ? "," : "", count, 100.0 * within / std::max<size_t>(1, pairs.size()), shorter, worst, ms);
  }
  std::printf("]}\n");
  return 0;
}

// Points uniform over a mesh's area (the control points of the benchmark's random polygons, as the
// wasm benchmark draws them).
class AreaPoints {
 public:
  AreaPoints(const TriMesh& mesh, unsigned seed) : rng_(seed) {
    std::vector<double> area(mesh.triangles.size());
    for (size_t f = 0; f < area.size(); ++f) {
      const auto& t = mesh.triangles[f];
      area[f] = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm();
    }
    face_ = std::discrete_distribution<int>(area.begin(), area.end());
  }
  MeshPoint operator()() {
    double a = u_(rng_), b = u_(rng_);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    return MeshPoint{face_(rng_), splinekit::Vec2(a, b)};
  }

 private:
  std::mt19937 rng_;
  std::discrete_distribution<int> face_;
  std::uniform_real_distribution<double> u_{0, 1};
};

static int curves(const std::string& file, int polygons, unsigned seed, bool lengths, const std::string& guide) {
  const TriMesh mesh = testing::build(testing::read_mesh(file));
  const int nf = static_cast<int>(mesh.triangles.size());
  GeodesicSolver solver(mesh);
  if (!guide.empty()) {
    const Arrays coarse = testing::read_mesh(guide);
    std::string error;
    if (solver.set_coarse_guide(coarse.triangles.data(), coarse.faces(), error) != MeshStatus::kOk)
      throw std::runtime_error(error);
  }
  int guided = 0;
  CurveTracer tracer(solver);
  AreaPoints point(mesh, seed);
  TraceOptions options;
  options.scheme = Scheme::kOLR;
  options.levels = 5;
  std::vector<MeshPoint> polyline;
  std::vector<double> ms, curve_length;
  std::vector<std::array<double, 6>> counters;
  for (int i = 0; i < polygons; ++i) {
    const ControlPolygon polygon = {point(), point(), point(), point()};
    tracer.stats = TraceStats{};
    const double t0 = thread_ms();
    tracer.trace(polygon, options, polyline);
    ms.push_back(thread_ms() - t0);
    const TraceStats& s = tracer.stats;
    guided += s.paths.guided;
    counters.push_back({double(s.shortest_paths), double(s.seeded_paths), double(s.paths.visited_nodes),
                        double(s.paths.strip_faces), double(s.paths.passes), double(s.paths.accepted_flips)});
    double len = 0;
    for (size_t k = 0; k + 1 < polyline.size(); ++k)
      len += (eval_position(mesh, polyline[k + 1]) - eval_position(mesh, polyline[k])).norm();
    curve_length.push_back(len);
  }
  auto quantile = [](std::vector<double> x, double q) {
    std::sort(x.begin(), x.end());
    return x.empty() ? 0.0 : x[std::min(x.size() - 1, static_cast<size_t>(q * x.size()))];
  };
  double total = 0;
  for (double x : ms) total += x;
  std::printf(
      "{\"triangles\":%d,\"curves\":%d,\"total_ms\":%.1f,\"median_ms\":%.3f,\"p90_ms\":%.3f,\"p99_ms\":%.3f,\"max_ms\":"
      "%.3f",
      nf, polygons, total, quantile(ms, 0.5), quantile(ms, 0.9), quantile(ms, 0.99), quantile(ms, 1));
  if (!guide.empty())
    std::printf(",\"guide_triangles\":%zu,\"guide_bytes_per_triangle\":%.1f,\"guided\":%d",
                solver.coarse_guide()->coarse().triangles.size(), double(solver.coarse_guide()->bytes()) / nf, guided);
  std::printf(",\"bytes_per_triangle\":%.1f", double(mesh_bytes(mesh) + solver.bytes()) / nf);
  const char* names[] = {"searched", "seeded", "nodes", "strip_faces", "passes", "flips"};
  for (int k = 0; k < 6; ++k) {
    std::vector<double> c;
    for (const auto& x : counters) c.push_back(x[k]);
    std::printf(",\"%s\":[%.0f,%.0f]", names[k], quantile(c, 0.5), quantile(c, 0.99));
  }
  if (lengths) {
    std::printf(",\"lengths\":[");
    for (size_t i = 0; i < curve_length.size(); ++i) std::printf("%s%.15g", i ? "," : "", curve_length[i]);
    std::printf("]");
  }
  std::printf("}\n");
  return 0;
}

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "shape" && argc >= 4) return shape(argc, argv);
    if (mode == "exact" && argc >= 3) return exact(argv[2]);
    if (mode == "search" && argc >= 5) return search(argv[2], std::atoi(argv[3]), std::atoi(argv[4]));
    if (mode == "steiner" && argc >= 6)
      return steiner(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), std::atoi(argv[5]));
    if (mode == "curves" && argc >= 5) {
      std::string guide;  // [lengths] [<guide.obj>: a decimation over the mesh's vertices]
      bool lengths = false;
      for (int i = 5; i < argc; ++i) std::string(argv[i]) == "lengths" ? void(lengths = true) : void(guide = argv[i]);
      return curves(argv[2], std::atoi(argv[3]), std::atoi(argv[4]), lengths, guide);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "surface_scale_bench: %s\n", e.what());
    return 1;
  }
  std::fprintf(
      stderr,
      "usage: surface_scale_bench shape coil|knot|folded|uvsphere|noisy|noisy-cube|small-noisy-coil|small-noisy-folded "
      "<out.obj> [<in mesh>]\n"
      "       surface_scale_bench exact <mesh>  (pairs on stdin)\n"
      "       surface_scale_bench search <mesh> <pairs> <seed>\n"
      "       surface_scale_bench steiner <mesh> <sources> <targets> <seed>\n"
      "       surface_scale_bench curves <mesh> <polygons> <seed> [lengths] [<guide.obj>]\n");
  return 2;
}
