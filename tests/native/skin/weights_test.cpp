// Harmonic and bounded biharmonic weights on a regular and an irregular grid mesh: interpolation,
// partition of unity, linear precision, KKT optimality of the BBW quadratic program, and the
// weights read back at points. The operators and point location have their own tests.
#include "skin/weights.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "skin/operators.h"
#include "skin/point_location.h"
#include "test_meshes.h"

using namespace splinekit::skin;

namespace {

using test_meshes::boundary_vertices;
using test_meshes::grid_mesh;
using test_meshes::Mesh;

// Vertex nearest to (x,y).
int32_t nearest_vertex(const Mesh& m, double x, double y) {
  int32_t best = 0;
  for (int v = 1; v < m.nv(); ++v)
    if (std::hypot(m.V[2 * v] - x, m.V[2 * v + 1] - y) < std::hypot(m.V[2 * best] - x, m.V[2 * best + 1] - y)) best = v;
  return best;
}

std::vector<int32_t> interior_handles(const Mesh& m) {
  return {nearest_vertex(m, 0.2, 0.2), nearest_vertex(m, 0.8, 0.25), nearest_vertex(m, 0.5, 0.8),
          nearest_vertex(m, 0.15, 0.9), nearest_vertex(m, 0.55, 0.45)};
}

Eigen::SparseMatrix<double> bilaplacian(const Mesh& m, MassType type) {
  Eigen::SparseMatrix<double> L, M;
  cotangent_laplacian(m.view(), L);
  mass_matrix(m.view(), type, M);
  return L * (M.diagonal().cwiseInverse().asDiagonal() * L);
}

// Column j of a #V by h row-major array.
Eigen::VectorXd column(const std::vector<double>& W, int h, int j) {
  Eigen::VectorXd c(W.size() / h);
  for (int v = 0; v < c.size(); ++v) c[v] = W[size_t(v) * h + j];
  return c;
}

// Unconstrained biharmonic weights of handle j (the BBW objective without bounds), by a direct solve.
Eigen::VectorXd unconstrained_biharmonic(const Mesh& m, const std::vector<int32_t>& handles, int j) {
  const Eigen::SparseMatrix<double> Q = bilaplacian(m, MassType::kVoronoi);
  std::vector<int> slot(m.nv(), 0), free;
  for (int32_t hv : handles) slot[hv] = -1;
  for (int v = 0; v < m.nv(); ++v)
    if (slot[v] == 0) slot[v] = int(free.size()), free.push_back(v);
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free.size());
  for (int c = 0; c < Q.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(Q, c); it; ++it) {
      if (slot[it.row()] < 0) continue;
      if (slot[c] >= 0)
        t.emplace_back(slot[it.row()], slot[c], it.value());
      else if (c == handles[j])
        rhs[slot[it.row()]] -= it.value();
    }
  Eigen::SparseMatrix<double> Qff(free.size(), free.size());
  Qff.setFromTriplets(t.begin(), t.end());
  const Eigen::VectorXd x = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(Qff).solve(rhs);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(m.nv());
  for (size_t k = 0; k < free.size(); ++k) w[free[k]] = x[k];
  w[handles[j]] = 1;
  return w;
}

class WeightsOnMeshes : public ::testing::TestWithParam<bool> {
 protected:
  Mesh mesh = grid_mesh(16, GetParam());
};

}  // namespace

TEST_P(WeightsOnMeshes, HarmonicInterpolatesSumsToOneAndIsHarmonicAtFreeVertices) {
  const std::vector<int32_t> handles = interior_handles(mesh);
  const int h = int(handles.size());
  std::vector<double> W(size_t(mesh.nv()) * h);
  const WeightsReport r = harmonic_weights(mesh.view(), handles.data(), h, W.data());
  ASSERT_TRUE(r.ok()) << r.error;
  for (int i = 0; i < h; ++i)
    for (int j = 0; j < h; ++j) EXPECT_EQ(W[size_t(handles[i]) * h + j], i == j ? 1.0 : 0.0);
  for (int v = 0; v < mesh.nv(); ++v) {
    double sum = 0;
    for (int j = 0; j < h; ++j) sum += W[size_t(v) * h + j];
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
  Eigen::SparseMatrix<double> L;
  cotangent_laplacian(mesh.view(), L);
  std::vector<char> is_handle(mesh.nv(), 0);
  for (int32_t v : handles) is_handle[v] = 1;
  double worst = 0, lo = 1, hi = 0;
  for (int j = 0; j < h; ++j) {
    const Eigen::VectorXd w = column(W, h, j), Lw = L * w;
    for (int v = 0; v < mesh.nv(); ++v)
      if (!is_handle[v]) worst = std::max(worst, std::abs(Lw[v]));
    lo = std::min(lo, w.minCoeff());
    hi = std::max(hi, w.maxCoeff());
  }
  EXPECT_LE(worst, 1e-9);
  if (!GetParam()) {
    // Right-triangle grid: every cotangent weight is ≥ 0, so the maximum principle holds.
    EXPECT_GE(lo, -1e-12);
    EXPECT_LE(hi, 1 + 1e-12);
  }
}

TEST_P(WeightsOnMeshes, HarmonicHasLinearPrecisionWithHandlesOnTheWholeBoundary) {
  // Dirichlet data on the whole boundary: Σ_i w_i(v) h_i reproduces v (L kills linear functions inside).
  const std::vector<int32_t> handles = boundary_vertices(16);
  const int h = int(handles.size());
  std::vector<double> W(size_t(mesh.nv()) * h);
  ASSERT_TRUE(harmonic_weights(mesh.view(), handles.data(), h, W.data()).ok());
  for (int v = 0; v < mesh.nv(); ++v) {
    double x = 0, y = 0;
    for (int j = 0; j < h; ++j) {
      x += W[size_t(v) * h + j] * mesh.V[2 * handles[j]];
      y += W[size_t(v) * h + j] * mesh.V[2 * handles[j] + 1];
    }
    EXPECT_NEAR(x, mesh.V[2 * v], 1e-12);
    EXPECT_NEAR(y, mesh.V[2 * v + 1], 1e-12);
  }
  // And so do the gradients: Σ_i ∇w_i h_iᵀ = I on every triangle.
  std::vector<double> G(size_t(mesh.nf()) * h * 2);
  triangle_weight_gradients(mesh.view(), W.data(), h, G.data());
  for (int t = 0; t < mesh.nf(); ++t) {
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
    for (int j = 0; j < h; ++j)
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) J(a, b) += mesh.V[2 * handles[j] + a] * G[(size_t(t) * h + j) * 2 + b];
    EXPECT_LE((J - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 1e-10) << "triangle " << t;
  }
}

// ---------------------------------------------------------------------------------------------
// Bounded biharmonic weights
// ---------------------------------------------------------------------------------------------

TEST_P(WeightsOnMeshes, BbwIsBoundedInterpolatesAndIsAPartitionOfUnity) {
  const std::vector<int32_t> handles = interior_handles(mesh);
  const int h = int(handles.size());
  std::vector<double> W(size_t(mesh.nv()) * h);
  const WeightsReport r = bbw_weights(mesh.view(), handles.data(), h, BbwOptions{}, W.data());
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.converged);
  ASSERT_EQ(r.iterations.size(), size_t(h));
  for (int it : r.iterations) {
    EXPECT_GE(it, 1);
    EXPECT_LE(it, BbwOptions{}.max_iterations);
  }
  for (double w : W) {
    EXPECT_GE(w, -1e-9);
    EXPECT_LE(w, 1 + 1e-9);
  }
  for (int i = 0; i < h; ++i)
    for (int j = 0; j < h; ++j) EXPECT_EQ(W[size_t(handles[i]) * h + j], i == j ? 1.0 : 0.0);
  for (int v = 0; v < mesh.nv(); ++v) {
    double sum = 0;
    for (int j = 0; j < h; ++j) sum += W[size_t(v) * h + j];
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
}

TEST_P(WeightsOnMeshes, BbwSatisfiesTheKktConditionsOfItsQuadraticProgram) {
  const std::vector<int32_t> handles = interior_handles(mesh);
  const int h = int(handles.size());
  BbwOptions options;
  options.partition_of_unity = false;   // the raw QP optimum
  options.multiplier_tolerance = 1e-4;  // near-exact multiplier signs (the default trades them for speed)
  std::vector<double> W(size_t(mesh.nv()) * h);
  const WeightsReport r = bbw_weights(mesh.view(), handles.data(), h, options, W.data());
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_TRUE(r.converged);

  const Eigen::SparseMatrix<double> Q = bilaplacian(mesh, options.mass);
  double scale = 0;  // ‖Q‖_∞: the size of a gradient entry for weights of size 1
  for (int v = 0; v < mesh.nv(); ++v) scale = std::max(scale, Q.row(v).cwiseAbs().sum());
  std::vector<char> is_handle(mesh.nv(), 0);
  for (int32_t v : handles) is_handle[v] = 1;
  int at_lower = 0, at_upper = 0;
  for (int j = 0; j < h; ++j) {
    const Eigen::VectorXd w = column(W, h, j), g = Q * w;  // gradient of ½ wᵀQw
    for (int v = 0; v < mesh.nv(); ++v) {
      if (is_handle[v]) continue;
      if (w[v] == 0.0) {
        ++at_lower;
        EXPECT_GE(g[v] / scale, -1e-6) << "multiplier of the lower bound at vertex " << v << ", handle " << j;
      } else if (w[v] == 1.0) {
        ++at_upper;
        EXPECT_LE(g[v] / scale, 1e-6) << "multiplier of the upper bound at vertex " << v << ", handle " << j;
      } else {
        EXPECT_LE(std::abs(g[v]) / scale, 1e-6) << "gradient at free vertex " << v << ", handle " << j;
      }
    }
  }
  EXPECT_GT(at_lower, 0) << "the lower bounds should be active somewhere";
}

TEST_P(WeightsOnMeshes, BbwDefaultToleranceStaysCloseToTheNearExactOptimum) {
  const std::vector<int32_t> handles = interior_handles(mesh);
  const int h = int(handles.size());
  BbwOptions tight;
  tight.multiplier_tolerance = 1e-4;
  std::vector<double> exact(size_t(mesh.nv()) * h), W(exact.size());
  const WeightsReport a = bbw_weights(mesh.view(), handles.data(), h, tight, exact.data());
  const WeightsReport b = bbw_weights(mesh.view(), handles.data(), h, BbwOptions{}, W.data());
  ASSERT_TRUE(a.ok() && b.ok());
  double worst = 0;
  for (size_t k = 0; k < W.size(); ++k) worst = std::max(worst, std::abs(W[k] - exact[k]));
  EXPECT_LE(worst, 3e-4);
}

TEST_P(WeightsOnMeshes, BbwDiffersFromUnconstrainedBiharmonicWhereThatGoesNegative) {
  const std::vector<int32_t> handles = interior_handles(mesh);
  const int h = int(handles.size());
  BbwOptions options;
  options.partition_of_unity = false;
  std::vector<double> W(size_t(mesh.nv()) * h);
  ASSERT_TRUE(bbw_weights(mesh.view(), handles.data(), h, options, W.data()).ok());
  int negative_handles = 0;
  for (int j = 0; j < h; ++j) {
    const Eigen::VectorXd free = unconstrained_biharmonic(mesh, handles, j), bbw = column(W, h, j);
    if (free.minCoeff() > -1e-3) continue;
    ++negative_handles;
    EXPECT_GE(bbw.minCoeff(), 0.0);
    EXPECT_GT((free - bbw).cwiseAbs().maxCoeff(), 1e-3);
  }
  EXPECT_GT(negative_handles, 0) << "the test needs a handle whose unconstrained weight goes negative";
}

TEST(Weights, OneHandleGetsWeightOneEverywhere) {
  const Mesh mesh = grid_mesh(6, true);
  const int32_t handle = 10;
  std::vector<double> W(mesh.nv());
  ASSERT_TRUE(bbw_weights(mesh.view(), &handle, 1, BbwOptions{}, W.data()).ok());
  for (double w : W) EXPECT_NEAR(w, 1.0, 1e-12);
  ASSERT_TRUE(harmonic_weights(mesh.view(), &handle, 1, W.data()).ok());
  for (double w : W) EXPECT_NEAR(w, 1.0, 1e-12);
}

TEST(Weights, BbwTerminatesWhenExactTolerancesMakeTheActiveSetCycle) {
  // With zero tolerances, rounding makes plain PDAS cycle on this mesh (a few rim vertices flip
  // between free and bound); the anti-cycling rule pins them so that the sets settle.
  const Mesh mesh = grid_mesh(24, false);
  const std::vector<int32_t> handles = {547, 553, 231, 384, 496, 307};
  const int h = int(handles.size());
  BbwOptions exact;
  exact.bound_tolerance = 0;
  exact.multiplier_tolerance = 0;
  std::vector<double> W(size_t(mesh.nv()) * h), reference(W.size());
  const WeightsReport r = bbw_weights(mesh.view(), handles.data(), h, exact, W.data());
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.converged);
  RecordProperty("pinned", r.pinned);
  BbwOptions tight;
  tight.multiplier_tolerance = 1e-4;
  ASSERT_TRUE(bbw_weights(mesh.view(), handles.data(), h, tight, reference.data()).ok());
  double worst = 0;
  for (size_t k = 0; k < W.size(); ++k) {
    EXPECT_TRUE(W[k] >= 0 && W[k] <= 1);
    worst = std::max(worst, std::abs(W[k] - reference[k]));
  }
  EXPECT_LE(worst, 1e-4);
}

TEST(Weights, BbwReportsWhenTheIterationCapIsHit) {
  const Mesh mesh = grid_mesh(16, false);
  const std::vector<int32_t> handles = interior_handles(mesh);
  BbwOptions options;
  options.max_iterations = 1;  // only the unconstrained solve, which goes out of bounds
  std::vector<double> W(size_t(mesh.nv()) * handles.size());
  const WeightsReport r = bbw_weights(mesh.view(), handles.data(), int(handles.size()), options, W.data());
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r.converged);
  for (double w : W) EXPECT_TRUE(w >= 0 && w <= 1);
}

// ---------------------------------------------------------------------------------------------
// Weights at points
// ---------------------------------------------------------------------------------------------

TEST_P(WeightsOnMeshes, InterpolationAtVerticesAndCentroids) {
  const std::vector<int32_t> handles = interior_handles(mesh);
  const int h = int(handles.size());
  std::vector<double> W(size_t(mesh.nv()) * h);
  ASSERT_TRUE(bbw_weights(mesh.view(), handles.data(), h, BbwOptions{}, W.data()).ok());
  TriangleGrid grid;
  build_triangle_grid(mesh.view(), grid);

  std::vector<double> at_vertices(W.size());
  locate_and_interpolate(grid, mesh.view(), W.data(), h, mesh.V.data(), mesh.nv(), at_vertices.data());
  for (size_t k = 0; k < W.size(); ++k) EXPECT_NEAR(at_vertices[k], W[k], 1e-12);

  std::vector<double> centroids;
  for (int t = 0; t < mesh.nf(); ++t)
    for (int a = 0; a < 2; ++a)
      centroids.push_back(
          (mesh.V[2 * mesh.F[3 * t] + a] + mesh.V[2 * mesh.F[3 * t + 1] + a] + mesh.V[2 * mesh.F[3 * t + 2] + a]) / 3);
  std::vector<double> at_centroids(size_t(mesh.nf()) * h);
  locate_and_interpolate(grid, mesh.view(), W.data(), h, centroids.data(), mesh.nf(), at_centroids.data());
  for (int t = 0; t < mesh.nf(); ++t)
    for (int j = 0; j < h; ++j) {
      double mean = 0;
      for (int k = 0; k < 3; ++k) mean += W[size_t(mesh.F[3 * t + k]) * h + j] / 3;
      EXPECT_NEAR(at_centroids[size_t(t) * h + j], mean, 1e-12);
    }

  // Gradients at the centroids are the gradients of their triangles.
  std::vector<double> G(size_t(mesh.nf()) * h * 2), at(size_t(mesh.nf()) * h * 2);
  triangle_weight_gradients(mesh.view(), W.data(), h, G.data());
  locate_gradients(grid, mesh.view(), G.data(), h, centroids.data(), mesh.nf(), at.data());
  EXPECT_EQ(at, G);
}

// ---------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------

TEST(Weights, BadInputIsReportedByName) {
  const Mesh good = grid_mesh(3, false);
  const std::vector<int32_t> handles = {0, 5};
  auto error = [&](Mesh m, std::vector<int32_t> h) {
    return validate_weights_input(m.view(), h.data(), int(h.size()));
  };
  EXPECT_EQ(error(good, handles), "");

  Mesh m = good;
  m.V[7] = NAN;
  EXPECT_NE(error(m, handles).find("vertex 3 has a non-finite coordinate"), std::string::npos);
  m = good;
  m.F[4] = 99;
  EXPECT_NE(error(m, handles).find("triangle 1 refers to vertex 99"), std::string::npos);
  m = good;
  m.F[5] = m.F[4];
  EXPECT_NE(error(m, handles).find("triangle 1 repeats a vertex"), std::string::npos);
  m = good;
  m.V[2 * m.F[2]] = m.V[2 * m.F[1]], m.V[2 * m.F[2] + 1] = 0;  // vertex 2 of triangle 0 onto its edge 0-1
  EXPECT_NE(error(m, handles).find("is degenerate"), std::string::npos);
  m = good;
  m.V.push_back(5), m.V.push_back(5);  // a vertex used by no triangle
  EXPECT_NE(error(m, handles).find("vertex 16 belongs to no triangle"), std::string::npos);

  EXPECT_NE(error(good, {}).find("no handles"), std::string::npos);
  EXPECT_NE(error(good, {0, 16}).find("handle 1 is vertex 16, outside [0, 16)"), std::string::npos);
  EXPECT_NE(error(good, {4, 2, 4}).find("handles 0 and 2 are the same vertex 4"), std::string::npos);

  // Two separate squares, a handle in only one of them.
  m = good;
  const int nv = m.nv();
  for (int v = 0; v < nv; ++v) m.V.push_back(m.V[2 * v] + 3), m.V.push_back(m.V[2 * v + 1]);
  const size_t nf3 = m.F.size();
  for (size_t k = 0; k < nf3; ++k) m.F.push_back(m.F[k] + nv);
  EXPECT_NE(error(m, {0}).find("containing vertex 16 has no handle"), std::string::npos);
  EXPECT_EQ(error(m, {0, 20}), "");

  // The solvers refuse the same inputs and bad options, leaving the output untouched.
  std::vector<double> W(size_t(good.nv()) * 2, -7.0);
  const int32_t same[] = {3, 3};
  EXPECT_FALSE(harmonic_weights(good.view(), same, 2, W.data()).ok());
  BbwOptions bad;
  bad.max_iterations = 0;
  EXPECT_NE(bbw_weights(good.view(), handles.data(), 2, bad, W.data()).error.find("max iterations"), std::string::npos);
  bad = BbwOptions{};
  bad.bound_tolerance = -1;
  EXPECT_NE(bbw_weights(good.view(), handles.data(), 2, bad, W.data()).error.find("bound tolerance"),
            std::string::npos);
  bad = BbwOptions{};
  bad.multiplier_tolerance = NAN;
  EXPECT_NE(bbw_weights(good.view(), handles.data(), 2, bad, W.data()).error.find("multiplier tolerance"),
            std::string::npos);
  for (double w : W) EXPECT_EQ(w, -7.0);
}

INSTANTIATE_TEST_SUITE_P(RegularAndIrregular, WeightsOnMeshes, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "Irregular" : "Regular";
                         });
