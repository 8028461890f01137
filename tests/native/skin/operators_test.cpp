// The discrete operators against their identities: the cotangent Laplacian's symmetry, zero row
// sums and linear precision, the mass matrices' total area and the obtuse-triangle split, and
// the gradients of the coordinate functions.
#include "skin/operators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_meshes.h"

using namespace splinekit::skin;
using test_meshes::boundary_vertices;
using test_meshes::grid_mesh;
using test_meshes::Mesh;

namespace {

class OperatorsOnMeshes : public ::testing::TestWithParam<bool> {
 protected:
  Mesh mesh = grid_mesh(16, GetParam());
};

}  // namespace

TEST_P(OperatorsOnMeshes, LaplacianIsSymmetricWithZeroRowSumsAndKillsLinearFunctionsInside) {
  Eigen::SparseMatrix<double> L;
  cotangent_laplacian(mesh.view(), L);
  ASSERT_EQ(L.rows(), mesh.nv());
  const Eigen::SparseMatrix<double> Lt = L.transpose();
  EXPECT_LE((L - Lt).norm(), 1e-14 * L.norm());
  const double scale = L.cwiseAbs().toDense().maxCoeff();
  const Eigen::VectorXd rows = L * Eigen::VectorXd::Ones(mesh.nv());
  EXPECT_LE(rows.cwiseAbs().maxCoeff(), 1e-13 * scale);
  // L x = 0 at interior vertices for the coordinate functions (the cotangent Laplacian's linear precision).
  Eigen::VectorXd x(mesh.nv()), y(mesh.nv());
  for (int v = 0; v < mesh.nv(); ++v) x[v] = mesh.V[2 * v], y[v] = mesh.V[2 * v + 1];
  const Eigen::VectorXd Lx = L * x, Ly = L * y;
  std::vector<char> on_boundary(mesh.nv(), 0);
  for (int32_t b : boundary_vertices(16)) on_boundary[b] = 1;
  for (int v = 0; v < mesh.nv(); ++v)
    if (!on_boundary[v]) {
      EXPECT_LE(std::abs(Lx[v]), 1e-12 * scale);
      EXPECT_LE(std::abs(Ly[v]), 1e-12 * scale);
    }
  // Negative semi-definite: the diagonal is negative.
  EXPECT_LT(L.diagonal().maxCoeff(), 0.0);
}

TEST_P(OperatorsOnMeshes, MassMatricesArePositiveAndSumToTheArea) {
  for (MassType type : {MassType::kBarycentric, MassType::kVoronoi}) {
    Eigen::SparseMatrix<double> M;
    mass_matrix(mesh.view(), type, M);
    EXPECT_EQ(M.nonZeros(), mesh.nv());
    EXPECT_NEAR(M.diagonal().sum(), 1.0, 1e-13);
    EXPECT_GT(M.diagonal().minCoeff(), 0.0);
  }
}

TEST(Operators, VoronoiMassOfAnObtuseTriangleSplitsHalfAndQuarters) {
  // Obtuse at vertex 2: area 1, so ½ there and ¼ at the others.
  const double V[] = {0, 0, 4, 0, 2, 0.5};
  const int32_t F[] = {0, 1, 2};
  Eigen::SparseMatrix<double> M;
  mass_matrix({V, 3, F, 1}, MassType::kVoronoi, M);
  EXPECT_NEAR(M.coeff(0, 0), 0.25, 1e-15);
  EXPECT_NEAR(M.coeff(1, 1), 0.25, 1e-15);
  EXPECT_NEAR(M.coeff(2, 2), 0.5, 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Harmonic weights
// ---------------------------------------------------------------------------------------------

TEST(Operators, GradientsOfTheCoordinateFunctionsAreTheIdentity) {
  const Mesh mesh = grid_mesh(8, true);
  std::vector<double> G(size_t(mesh.nf()) * 4);
  triangle_weight_gradients(mesh.view(), mesh.V.data(), 2, G.data());  // "weights" x and y
  for (int t = 0; t < mesh.nf(); ++t) {
    EXPECT_NEAR(G[4 * t], 1.0, 1e-12);
    EXPECT_NEAR(G[4 * t + 1], 0.0, 1e-12);
    EXPECT_NEAR(G[4 * t + 2], 0.0, 1e-12);
    EXPECT_NEAR(G[4 * t + 3], 1.0, 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(RegularAndIrregular, OperatorsOnMeshes, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "Irregular" : "Regular";
                         });
