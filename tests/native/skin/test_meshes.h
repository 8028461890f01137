// Small 2D meshes shared by the skin tests: the unit square as a regular or jittered grid.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "skin/mesh_view.h"

namespace splinekit::skin::test_meshes {

struct Mesh {
  std::vector<double> V;
  std::vector<int32_t> F;
  MeshView2 view() const { return {V.data(), int(V.size() / 2), F.data(), int(F.size() / 3)}; }
  int nv() const { return int(V.size() / 2); }
  int nf() const { return int(F.size() / 3); }
  int at(int n, int i, int j) const { return j * (n + 1) + i; }
};

// The unit square as an n by n grid of squares, two triangles each. irregular: interior vertices
// jittered by up to 0.3 of the spacing and diagonals chosen at random (still a valid mesh).
inline Mesh grid_mesh(int n, bool irregular, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = double(i) / n, y = double(j) / n;
      if (irregular && i > 0 && i < n && j > 0 && j < n) x += jitter(rng) / n, y += jitter(rng) / n;
      m.V.push_back(x);
      m.V.push_back(y);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = m.at(n, i, j), b = m.at(n, i + 1, j), c = m.at(n, i + 1, j + 1), d = m.at(n, i, j + 1);
      if (irregular && rng() % 2) {
        m.F.insert(m.F.end(), {a, b, d, b, c, d});
      } else {
        m.F.insert(m.F.end(), {a, b, c, a, c, d});
      }
    }
  return m;
}

// The vertices on the boundary of grid_mesh(n, ·).
inline std::vector<int32_t> boundary_vertices(int n) {
  std::vector<int32_t> out;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (i == 0 || j == 0 || i == n || j == n) out.push_back(j * (n + 1) + i);
  return out;
}

}  // namespace splinekit::skin::test_meshes
