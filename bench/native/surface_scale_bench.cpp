// Native side of the "surface at scale" benchmark (bench/surface-scale.mjs runs it):
//
//   surface_scale_bench shape coil|folded|noisy <out.obj> [<in mesh> for noisy]
//       writes a generated mesh (tests/native/surface/test_meshes.h: the same shapes the tests use,
//       at benchmark size): the coil (8 turns, tube radius 0.12, pitch 0.3, 4000 x 48 quads,
//       384k triangles), a body with two limbs folded against it (3000 x 64 quads, 384k triangles),
//       or <in mesh> with normal noise of +-0.3 mean edge lengths (seed 3).
//   surface_scale_bench exact <mesh>   (pairs "a b" of file vertex indices on stdin)
//       prints {"distances":[...]}: the exact polyhedral geodesic distance of every pair
//       (tests/native/reference/exact_geodesic.h, MMP windows; one run per distinct source) on the
//       file's own vertices and triangles, and {"ms_per_source":..}.
//   surface_scale_bench search <mesh> <pairs> <seed>
//       phase (i) alone, with and without landmarks, on random face pairs: nodes expanded and time
//       per search for the kDual and kRefined graphs, and the landmark precompute.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "../../tests/native/reference/exact_geodesic.h"
#include "../../tests/native/surface/test_meshes.h"
#include "surface/geodesic.h"

using namespace splinekit::surface;
using splinekit::surface::testing::Arrays;
using Clock = std::chrono::steady_clock;

static double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
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
  if (kind == "folded") return write_obj(testing::folded_body(3000, 64), out);
  if (kind == "noisy" && argc > 4) return write_obj(testing::noisy(testing::read_mesh(argv[4]), 0.3, 3), out);
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

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "shape" && argc >= 4) return shape(argc, argv);
    if (mode == "exact" && argc >= 3) return exact(argv[2]);
    if (mode == "search" && argc >= 5) return search(argv[2], std::atoi(argv[3]), std::atoi(argv[4]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "surface_scale_bench: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr,
               "usage: surface_scale_bench shape coil|folded|noisy <out.obj> [<in mesh>]\n"
               "       surface_scale_bench exact <mesh>  (pairs on stdin)\n"
               "       surface_scale_bench search <mesh> <pairs> <seed>\n");
  return 2;
}
