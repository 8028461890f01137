// Â = Mᵀ D M assembled from per-face dense blocks (Subdivision::gram_lower, what the rig factorizes)
// against two independent constructions: the level-by-level sparse products of the chain
// (Subdivision::gram) and, on the smaller cages, Eigen's own sparse product of the explicit M;
// Ŵ = Mᵀ G from the same pass (Subdivision::normal_equations) against S_1ᵀ ⋯ S_kᵀ G level by level
// (apply_transpose) and Eigen's Mᵀ G.
// Every shared cage (quads, triangles, pentagons, creases, boundaries), a sheet with corners, a
// cage with a vertex no face uses, levels 1 to 3, random positive D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "skin3d/subdivision.h"
#include "test_cages.h"

namespace splinekit::skin3d {
namespace {

using namespace test_cages;
using Sparse = Eigen::SparseMatrix<double>;

// Positive weights with a spread (so that a group's rows weighted wrongly would show).
Eigen::VectorXd random_weights(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.1, 2.0);
  Eigen::VectorXd D(n);
  for (int r = 0; r < n; ++r) D[r] = u(rng);
  return D;
}

// max |lower(reference) − lower| over both patterns, and max |reference|.
void expect_same_lower(const Sparse& reference, const Sparse& lower, double rel, const std::string& what) {
  ASSERT_EQ(lower.rows(), reference.rows()) << what;
  ASSERT_EQ(lower.cols(), reference.cols()) << what;
  // The assembled matrix holds nothing above the diagonal.
  for (int c = 0; c < lower.outerSize(); ++c)
    for (Sparse::InnerIterator it(lower, c); it; ++it) ASSERT_GE(it.row(), it.col()) << what;
  const Sparse ref_lower = reference.triangularView<Eigen::Lower>();
  const Sparse diff = ref_lower - lower;
  double scale = 0, worst = 0;
  for (int c = 0; c < ref_lower.outerSize(); ++c)
    for (Sparse::InnerIterator it(ref_lower, c); it; ++it) scale = std::max(scale, std::abs(it.value()));
  for (int c = 0; c < diff.outerSize(); ++c)
    for (Sparse::InnerIterator it(diff, c); it; ++it) worst = std::max(worst, std::abs(it.value()));
  ASSERT_GT(scale, 0) << what;
  EXPECT_LE(worst, rel * scale) << what << ": largest difference " << worst << " of " << scale;
  // Same non-zeros: every entry of the reference above rounding is in the assembled pattern.
  int missing = 0;
  for (int c = 0; c < ref_lower.outerSize(); ++c)
    for (Sparse::InnerIterator it(ref_lower, c); it; ++it)
      if (std::abs(it.value()) > rel * scale && lower.coeff(it.row(), it.col()) == 0.0) ++missing;
  EXPECT_EQ(missing, 0) << what;
}

void check(const Cage& cage, int levels, const std::string& name, bool with_explicit_product) {
  Subdivision s;
  s.build(cage.mesh(), levels);
  const Eigen::VectorXd D = random_weights(s.refined_vertex_count(), unsigned(7 * levels + cage.nv()));
  const Sparse lower = s.gram_lower(D);
  const std::string what = name + " level " + std::to_string(levels);
  expect_same_lower(s.gram(D), lower, 1e-13, what + " vs the chain of products");
  // Ŵ = Mᵀ G in the same pass, against the level-by-level transposes (and Eigen's Mᵀ G).
  const int cols = 6;
  auto g_row = [&](int r, double* g) {
    for (int c = 0; c < cols; ++c) g[c] = std::sin(0.7 * r + 1.3 * c) + 0.25 * c;
  };
  Eigen::MatrixXd MtG;
  const Sparse both = s.normal_equations(D, cols, g_row, MtG);
  EXPECT_EQ(Sparse(both - lower).norm(), 0.0) << what << ": normal_equations' Â differs from gram_lower's";
  const Eigen::MatrixXd chain = s.apply_transpose(cols, g_row);
  ASSERT_EQ(MtG.rows(), chain.rows()) << what;
  ASSERT_EQ(MtG.cols(), chain.cols()) << what;
  EXPECT_LE((MtG - chain).cwiseAbs().maxCoeff(), 1e-13 * chain.cwiseAbs().maxCoeff()) << what << " Ŵ";
  if (with_explicit_product) {
    const Eigen::SparseMatrix<double> M = s.compose();
    const Sparse reference = Sparse(M.transpose()) * D.asDiagonal() * M;
    expect_same_lower(reference, lower, 1e-13, what + " vs Eigen's Mᵀ D M");
    Eigen::MatrixXd G(s.refined_vertex_count(), cols);
    std::vector<double> g(cols);
    for (int r = 0; r < G.rows(); ++r) {
      g_row(r, g.data());
      for (int c = 0; c < cols; ++c) G(r, c) = g[c];
    }
    const Eigen::MatrixXd direct = Sparse(M.transpose()) * G;
    EXPECT_LE((MtG - direct).cwiseAbs().maxCoeff(), 1e-13 * direct.cwiseAbs().maxCoeff()) << what << " Ŵ vs Mᵀ G";
  }
}

TEST(SubdivisionGram, FaceBlocksEqualTheSparseProductsOnEveryCage) {
  for (const char* name : kSharedCages) {
    const Cage cage = read_cage(name);
    for (int levels = 1; levels <= 3; ++levels) check(cage, levels, name, cage.nv() < 1000 || levels < 3);
  }
}

TEST(SubdivisionGram, SheetWithBoundaryAndCornersAndLevelFour) {
  const Cage sheet = test_cages::sheet(5, 3);
  for (int levels = 1; levels <= 4; ++levels) check(sheet, levels, "sheet", true);
}

TEST(SubdivisionGram, VertexNoFaceUsesKeepsItsOwnWeight) {
  Cage cage = read_cage("cube_quad.obj");
  cage.V.insert(cage.V.end(), {5.0, 5.0, 5.0});  // vertex 8: in no face
  for (int levels = 1; levels <= 3; ++levels) {
    check(cage, levels, "cube with a lone vertex", true);
    Subdivision s;
    s.build(cage.mesh(), levels);
    const Eigen::VectorXd D = random_weights(s.refined_vertex_count(), 3);
    // Its row of M is e_8 (carried along unchanged), so Â(8, 8) = D_8 and nothing else in column 8.
    const Sparse lower = s.gram_lower(D);
    EXPECT_DOUBLE_EQ(lower.coeff(8, 8), D[8]);
    for (int v = 0; v < 8; ++v) EXPECT_EQ(lower.coeff(8, v), 0.0);
  }
}

TEST(SubdivisionGram, CarRefinedOnceAtLevelTwoWithDecayedCreases) {
  // The car refined once (its crease tags decayed) as a cage of its own, as the benchmark's
  // larger cages are made: semi-sharp creases now fractional or smooth, boundaries kept.
  const Cage car = read_cage("catmark_car.obj");
  Subdivision once;
  once.build(car.mesh(), 1, true);
  const PolyMesh& fine = once.refined_mesh();
  Cage refined;
  refined.V.assign(3 * size_t(fine.vertex_count), 0.0);
  once.apply(car.V.data(), 3, refined.V.data());
  refined.indices = fine.face_vertices;
  refined.sizes.assign(size_t(fine.face_count()), 4);
  for (int e = 0; e < fine.edge_count(); ++e)
    if (!fine.boundary_edge(e) && fine.edge_sharpness[e] > 0)
      refined.creases.push_back({fine.edge_vertices[2 * e], fine.edge_vertices[2 * e + 1], fine.edge_sharpness[e]});
  ASSERT_GT(refined.creases.size(), 0u);
  check(refined, 2, "car refined once", false);
}

}  // namespace
}  // namespace splinekit::skin3d
