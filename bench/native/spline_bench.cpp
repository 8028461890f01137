// Native timing of the spline kernels on a spline set dumped by bench/run.mjs, so the benchmark
// can report wasm/native ratios for the same work on the same data.
//
// usage: spline_bench <splines.bin> <repeats>
// splines.bin: int32 spline count S, int32 point count P, then S int32 starts, S int32 counts,
// S int32 closed flags, 2P float64 coordinates (little endian).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

#include "common/continuity.h"
#include "common/spline_set.h"

using namespace splinekit;

template <class F>
double median_ms(int repeats, F&& f) {
  for (int i = 0; i < 3; ++i) f();  // warm-up
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto a = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: spline_bench <splines.bin> <repeats>\n");
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  int32_t S = 0, P = 0;
  in.read(reinterpret_cast<char*>(&S), 4);
  in.read(reinterpret_cast<char*>(&P), 4);
  SplineSet set;
  set.start.resize(S);
  set.count.resize(S);
  set.closed.resize(S);
  set.points.resize(2 * size_t(P));
  in.read(reinterpret_cast<char*>(set.start.data()), 4 * S);
  in.read(reinterpret_cast<char*>(set.count.data()), 4 * S);
  in.read(reinterpret_cast<char*>(set.closed.data()), 4 * S);
  in.read(reinterpret_cast<char*>(set.points.data()), 16 * size_t(P));
  if (!in || !validate(set).empty()) {
    std::fprintf(stderr, "spline_bench: bad input %s\n", argv[1]);
    return 1;
  }
  const int repeats = std::atoi(argv[2]);
  std::vector<double> bounds(4 * size_t(S)), samples(2 * 16 * size_t(total_segments(set)));
  std::vector<JunctionInfo> tags(size_t(total_junctions(set)));
  const ContinuityOptions options;
  const double b = median_ms(repeats, [&] { spline_set_bounds(set, bounds.data()); });
  const double c = median_ms(repeats, [&] { spline_set_classify(set, options, tags.data()); });
  const double s = median_ms(repeats, [&] { spline_set_sample(set, 16, samples.data()); });
  std::printf("{\"bounds_ms\":%.6f,\"classify_ms\":%.6f,\"sample16_ms\":%.6f}\n", b, c, s);
  return 0;
}
