#include "operators.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace splinekit::skin {

namespace {

// |a × b|: twice the area of the triangle spanned by a and b, in 2D or 3D.
double cross_norm(const Vec2& a, const Vec2& b) { return std::abs(cross(a, b)); }
double cross_norm(const Vec3& a, const Vec3& b) { return a.cross(b).norm(); }

template <class Mesh>
void cotangent_laplacian_of(const Mesh& m, Eigen::SparseMatrix<double>& L) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * size_t(m.triangle_count));
  for (int t = 0; t < m.triangle_count; ++t) {
    const int32_t* f = m.triangle(t);
    for (int k = 0; k < 3; ++k) {
      // Edge (i, j) and the angle at o opposite it: cot = (a·b) / |a×b| with a = i − o, b = j − o.
      const int o = f[k], i = f[(k + 1) % 3], j = f[(k + 2) % 3];
      const auto po = m.position(o);
      const auto a = (m.position(i) - po).eval(), b = (m.position(j) - po).eval();
      const double w = 0.5 * a.dot(b) / cross_norm(a, b);
      entries.emplace_back(i, j, w);
      entries.emplace_back(j, i, w);
      entries.emplace_back(i, i, -w);
      entries.emplace_back(j, j, -w);
    }
  }
  L.resize(m.vertex_count, m.vertex_count);
  L.setFromTriplets(entries.begin(), entries.end());
}

template <class Mesh>
void mass_matrix_of(const Mesh& m, MassType type, Eigen::SparseMatrix<double>& M) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(m.vertex_count);
  for (int t = 0; t < m.triangle_count; ++t) {
    const int32_t* f = m.triangle(t);
    const double A =
        0.5 * cross_norm((m.position(f[1]) - m.position(f[0])).eval(), (m.position(f[2]) - m.position(f[0])).eval());
    if (type == MassType::kBarycentric) {
      for (int k = 0; k < 3; ++k) area[f[k]] += A / 3;
      continue;
    }
    // Squared length of the edge opposite vertex k, and the cotangent of the angle at k.
    double len2[3], cot[3];
    for (int k = 0; k < 3; ++k) {
      const auto o = m.position(f[k]), p = m.position(f[(k + 1) % 3]), q = m.position(f[(k + 2) % 3]);
      len2[k] = (q - p).squaredNorm();
      cot[k] = (p - o).dot(q - o) / (2 * A);
    }
    const int obtuse = cot[0] < 0 ? 0 : cot[1] < 0 ? 1 : cot[2] < 0 ? 2 : -1;
    for (int k = 0; k < 3; ++k) {
      if (obtuse >= 0) {
        // The circumcenter lies outside: split the area ½ to the obtuse corner, ¼ to the others.
        area[f[k]] += k == obtuse ? A / 2 : A / 4;
      } else {
        // Voronoi cell of corner k: the two incident edges, each weighted by its opposite cotangent.
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        area[f[k]] += (len2[a] * cot[a] + len2[b] * cot[b]) / 8;
      }
    }
  }
  M.resize(m.vertex_count, m.vertex_count);
  M.reserve(Eigen::VectorXi::Ones(m.vertex_count));
  for (int v = 0; v < m.vertex_count; ++v) M.insert(v, v) = area[v];
  M.makeCompressed();
}

}  // namespace

void cotangent_laplacian(const MeshView2& m, Eigen::SparseMatrix<double>& L) { cotangent_laplacian_of(m, L); }
void cotangent_laplacian_3d(const MeshView3& m, Eigen::SparseMatrix<double>& L) { cotangent_laplacian_of(m, L); }
void mass_matrix(const MeshView2& m, MassType type, Eigen::SparseMatrix<double>& M) { mass_matrix_of(m, type, M); }
void mass_matrix_3d(const MeshView3& m, MassType type, Eigen::SparseMatrix<double>& M) { mass_matrix_of(m, type, M); }

void triangle_weight_gradients(const MeshView2& m, const double* W, int handle_count, double* G) {
  for (int t = 0; t < m.triangle_count; ++t) {
    const int32_t* f = m.triangle(t);
    const double twice_area = orient(m.position(f[0]), m.position(f[1]), m.position(f[2]));
    double* g = G + size_t(t) * handle_count * 2;
    std::fill(g, g + 2 * handle_count, 0.0);
    for (int k = 0; k < 3; ++k) {
      // ∇φ_k = rot90(e_k) / (2A_signed), e_k = the edge opposite corner k, rot90(x,y) = (−y,x).
      const Vec2 e = m.position(f[(k + 2) % 3]) - m.position(f[(k + 1) % 3]);
      const double gx = -e.y() / twice_area, gy = e.x() / twice_area;
      const double* w = W + size_t(f[k]) * handle_count;
      for (int i = 0; i < handle_count; ++i) {
        g[2 * i] += w[i] * gx;
        g[2 * i + 1] += w[i] * gy;
      }
    }
  }
}

}  // namespace splinekit::skin
