// Native timing harness for the Skin 3D precompute (issue 18): the phases of
// SubdivisionRig::setup + use_shepard + precompute on a shared cage, optionally refined first
// (as bench/skin3d.mjs does with refineCage), at level K with H handles (farthest points).
//
//   skin3d_bench <cage.obj> [refine=2] [levels=3] [handles=4] [runs=1] [phases]
//
// Prints one JSON line per run: {"setup_ms","weights_ms","precompute_ms","total_ms",...}. With
// "phases": the fastest of `runs` calls of each precompute kernel alone instead (subdivision
// build, Â by face blocks, Â by the chain of sparse products, Ŵ = Mᵀ G), to compare kernels on a
// busy machine.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../../tests/native/skin3d/test_cages.h"
#include "skin3d/rig.h"

using namespace splinekit::skin3d;
using Clock = std::chrono::steady_clock;

static double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// The cage refined `levels` times as a new cage (positions, quads, decayed crease tags).
static test_cages::Cage refined_cage(const test_cages::Cage& c, int levels) {
  if (levels == 0) return c;
  Subdivision s;
  s.build(c.mesh(), levels, true);
  const PolyMesh& fine = s.refined_mesh();
  test_cages::Cage out;
  out.V.assign(3 * size_t(fine.vertex_count), 0.0);
  s.apply(c.V.data(), 3, out.V.data());
  out.indices = fine.face_vertices;
  out.sizes.assign(size_t(fine.face_count()), 4);
  for (int e = 0; e < fine.edge_count(); ++e)
    if (!fine.boundary_edge(e) && fine.edge_sharpness[e] > 0)
      out.creases.push_back({fine.edge_vertices[2 * e], fine.edge_vertices[2 * e + 1], fine.edge_sharpness[e]});
  return out;
}

// Farthest-point sampling of the cage vertices, starting from vertex 0.
static std::vector<double> farthest(const std::vector<double>& V, int count) {
  const int n = int(V.size() / 3);
  std::vector<double> d(size_t(n), INFINITY), out;
  int next = 0;
  for (int k = 0; k < count; ++k) {
    out.insert(out.end(), {V[3 * next], V[3 * next + 1], V[3 * next + 2]});
    int best = 0;
    for (int v = 0; v < n; ++v) {
      const double dx = V[3 * v] - out[3 * k], dy = V[3 * v + 1] - out[3 * k + 1], dz = V[3 * v + 2] - out[3 * k + 2];
      d[v] = std::min(d[v], dx * dx + dy * dy + dz * dz);
      if (d[v] > d[best]) best = v;
    }
    next = best;
  }
  return out;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: skin3d_bench <cage.obj> [refine=2] [levels=3] [handles=4] [runs=1]\n");
    return 2;
  }
  const std::string name = argv[1];
  const int refine = argc > 2 ? std::atoi(argv[2]) : 2, levels = argc > 3 ? std::atoi(argv[3]) : 3;
  const int H = argc > 4 ? std::atoi(argv[4]) : 4, runs = argc > 5 ? std::atoi(argv[5]) : 1;
  const test_cages::Cage cage = refined_cage(test_cages::read_cage(name), refine);
  const std::vector<double> handles = farthest(cage.V, H);
  if (argc > 6 && std::string(argv[6]) == "phases") {
    const PolyMesh mesh = cage.mesh();
    Subdivision s;
    double build = INFINITY, lower = INFINITY, products = INFINITY, transpose = INFINITY;
    for (int run = 0; run < runs; ++run) {
      const auto t0 = Clock::now();
      s.build(mesh, levels);
      build = std::min(build, ms_since(t0));
    }
    const Eigen::VectorXd D = Eigen::VectorXd::LinSpaced(s.refined_vertex_count(), 1.0, 2.0);
    double check = 0;
    for (int run = 0; run < runs; ++run) {
      const auto t0 = Clock::now();
      check += s.gram_lower(D).sum();
      lower = std::min(lower, ms_since(t0));
    }
    for (int run = 0; run < runs && levels <= 3; ++run) {
      const auto t0 = Clock::now();
      check -= 0.5 * (s.gram(D).sum() + s.gram(D).diagonal().sum());
      products = std::min(products, ms_since(t0) / 2);
    }
    for (int run = 0; run < runs; ++run) {
      const auto t0 = Clock::now();
      check += s.apply_transpose(4 * H, [&](int r, double* g) {
                  for (int c = 0; c < 4 * H; ++c) g[c] = D[r] * (1 + c);
                }).sum();
      transpose = std::min(transpose, ms_since(t0));
    }
    std::printf(
        "{\"build_ms\":%.1f,\"gram_lower_ms\":%.1f,\"gram_products_ms\":%.1f,\"apply_transpose_ms\":%.1f,"
        "\"check\":%.6g}\n",
        build, lower, products, transpose, check);
    return 0;
  }
  for (int run = 0; run < runs; ++run) {
    SubdivisionRig rig;
    const auto t0 = Clock::now();
    const std::string e = rig.setup(cage.V.data(), cage.nv(), cage.sizes.data(), cage.nf(), cage.indices.data(),
                                    cage.creases.data(), int(cage.creases.size()), levels, H);
    if (!e.empty()) {
      std::fprintf(stderr, "skin3d_bench: %s\n", e.c_str());
      return 1;
    }
    const double setup = ms_since(t0);
    const auto t1 = Clock::now();
    rig.use_shepard(handles.data(), 2.0);
    const double weights = ms_since(t1);
    const auto t2 = Clock::now();
    const std::string p = rig.precompute();
    if (!p.empty()) {
      std::fprintf(stderr, "skin3d_bench: %s\n", p.c_str());
      return 1;
    }
    const double precompute = ms_since(t2);
    // A checksum of O through one update with a fixed pose (so that runs can be compared).
    std::vector<double> T(12 * size_t(H), 0.0);
    for (int i = 0; i < H; ++i)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) T[12 * i + 4 * r + c] = (r == c ? 1.0 : 0.0) + 0.01 * std::sin(1.0 + i + 3 * r + c);
    const double* X = rig.update(T.data());
    double sum = 0;
    for (int k = 0; k < 3 * rig.cage_vertex_count(); ++k) sum += X[k] * (1 + k % 7);
    std::printf(
        "{\"cage\":\"%s\",\"refine\":%d,\"levels\":%d,\"handles\":%d,\"cage_vertices\":%d,\"refined_vertices\":%d,"
        "\"setup_ms\":%.1f,\"weights_ms\":%.1f,\"precompute_ms\":%.1f,\"total_ms\":%.1f,\"memory_M\":%zu,"
        "\"checksum\":%.15g}\n",
        name.c_str(), refine, levels, H, rig.cage_vertex_count(), rig.refined_vertex_count(), setup, weights,
        precompute, setup + weights + precompute, rig.memory_M(), sum);
  }
  return 0;
}
