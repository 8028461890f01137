// The supernodal Cholesky against Eigen's factorizations (SimplicialLLT in the same order, dense
// LLT, SimplicialLDLT) on several SPD matrices, and its report on matrices that are not SPD.
#include "skin/supernodal_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "skin/operators.h"
#include "test_meshes.h"

using namespace splinekit::skin;
using SpMat = Eigen::SparseMatrix<double>;

namespace {

// A symmetric matrix from (row, column, value) entries of its lower triangle, both triangles stored.
SpMat symmetric(int n, const std::vector<Eigen::Triplet<double>>& lower) {
  std::vector<Eigen::Triplet<double>> all(lower);
  for (const auto& t : lower)
    if (t.row() != t.col()) all.emplace_back(t.col(), t.row(), t.value());
  SpMat A(n, n);
  A.setFromTriplets(all.begin(), all.end());
  return A;
}

// Random sparse SPD: about `per_row` off-diagonal entries per row in [−1, 1], the diagonal one
// more than the row's absolute sum (strictly diagonally dominant).
SpMat random_spd(int n, int per_row, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1, 1);
  std::uniform_int_distribution<int> column(0, n - 1);
  std::vector<Eigen::Triplet<double>> lower;
  for (int r = 0; r < n; ++r)
    for (int k = 0; k < per_row / 2; ++k) {
      const int c = column(rng);
      if (c < r) lower.emplace_back(r, c, value(rng));
    }
  SpMat A = symmetric(n, lower);
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(n);
  for (int c = 0; c < n; ++c)
    for (SpMat::InnerIterator it(A, c); it; ++it) row_sum[it.row()] += std::abs(it.value());
  for (int r = 0; r < n; ++r) A.coeffRef(r, r) += row_sum[r] + 1;
  A.makeCompressed();
  return A;
}

// P A Pᵀ for the fill-reducing order `order` (order[k] = the row of A eliminated k-th).
SpMat reordered(const SpMat& A, const std::vector<int>& order) {
  std::vector<int> at(order.size());
  for (size_t k = 0; k < order.size(); ++k) at[order[k]] = int(k);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < A.outerSize(); ++c)
    for (SpMat::InnerIterator it(A, c); it; ++it) t.emplace_back(at[it.row()], at[c], it.value());
  SpMat B(A.rows(), A.cols());
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

std::vector<int> amd_order(const SpMat& A) {
  Eigen::AMDOrdering<int> amd;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p;
  amd(A, p);
  return std::vector<int>(p.indices().data(), p.indices().data() + p.size());
}

// Q_ff (or −L_ff + M_ff) of the jittered grid with the vertices in `fixed` removed.
SpMat free_block(const SpMat& Q, const std::vector<int>& fixed) {
  std::vector<int> slot(Q.rows(), 0);
  for (int v : fixed) slot[v] = -1;
  int n = 0;
  for (int& s : slot)
    if (s == 0) s = n++;
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < Q.outerSize(); ++c)
    for (SpMat::InnerIterator it(Q, c); it; ++it)
      if (slot[it.row()] >= 0 && slot[c] >= 0) t.emplace_back(slot[it.row()], slot[c], it.value());
  SpMat B(n, n);
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

struct Factored {
  SupernodalCholesky cholesky;
  bool ok = false;
};

// Solves A x = b with the supernodal Cholesky and with Eigen's SimplicialLDLT, and compares:
// each relative residual ≤ residual_tolerance, the two solutions within solution_tolerance
// (relative), and the factor against SimplicialLLT of the same postordered matrix.
void expect_agrees_with_eigen(const SpMat& A, double residual_tolerance, double solution_tolerance, unsigned seed = 1) {
  const int n = int(A.rows());
  SupernodalCholesky cholesky;
  ASSERT_TRUE(cholesky.factorize(A));
  EXPECT_EQ(cholesky.size(), n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1, 1);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = value(rng);

  Eigen::VectorXd x = b;
  cholesky.solve(x.data());
  Eigen::SimplicialLDLT<SpMat> ldlt(A);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd reference = ldlt.solve(b);
  const double norm_a = Eigen::MatrixXd(A).cwiseAbs().rowwise().sum().maxCoeff();  // ‖A‖∞
  auto residual = [&](const Eigen::VectorXd& y) {
    return (A * y - b).lpNorm<Eigen::Infinity>() / (norm_a * y.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
  };
  EXPECT_LE(residual(x), residual_tolerance);
  EXPECT_LE(residual(reference), residual_tolerance);
  EXPECT_LE((x - reference).lpNorm<Eigen::Infinity>(), solution_tolerance * reference.lpNorm<Eigen::Infinity>());

  // The Cholesky factor of an SPD matrix in a given order is unique: compare it, entry by entry,
  // with Eigen's column-by-column factor of the same (postordered) matrix.
  const std::vector<int>& post = cholesky.postorder();
  ASSERT_EQ(int(post.size()), n);
  EXPECT_EQ(std::set<int>(post.begin(), post.end()).size(), size_t(n));  // a permutation
  Eigen::SimplicialLLT<SpMat, Eigen::Lower, Eigen::NaturalOrdering<int>> llt(reordered(A, post));
  ASSERT_EQ(llt.info(), Eigen::Success);
  const Eigen::MatrixXd expected = Eigen::MatrixXd(SpMat(llt.matrixL()));
  const Eigen::MatrixXd actual = Eigen::MatrixXd(cholesky.factor());
  EXPECT_TRUE(actual.isLowerTriangular());
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

std::multiset<int> supernode_sizes(const SupernodalCholesky& c) {
  std::multiset<int> sizes;
  for (int s = 0; s < c.supernode_count(); ++s) sizes.insert(c.supernode_columns(s));
  return sizes;
}

}  // namespace

TEST(SupernodalCholesky, OneByOne) {
  SpMat A(1, 1);
  A.insert(0, 0) = 4;
  SupernodalCholesky c;
  ASSERT_TRUE(c.factorize(A));
  EXPECT_EQ(c.supernode_count(), 1);
  double x = 6;
  c.solve(&x);
  EXPECT_DOUBLE_EQ(x, 1.5);
  EXPECT_DOUBLE_EQ(c.factor().coeff(0, 0), 2.0);
}

TEST(SupernodalCholesky, RandomSparseSpdInNaturalAndAmdOrder) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const SpMat A = random_spd(300, 6, seed);
    expect_agrees_with_eigen(A, 1e-15, 1e-13, seed);
    expect_agrees_with_eigen(reordered(A, amd_order(A)), 1e-15, 1e-13, seed);
  }
}

TEST(SupernodalCholesky, CotangentLaplacianPlusMassAndBilaplacianWithHandlesRemoved) {
  const test_meshes::Mesh mesh = test_meshes::grid_mesh(14, true);
  SpMat L, M;
  cotangent_laplacian(mesh.view(), L);
  mass_matrix(mesh.view(), MassType::kVoronoi, M);
  const std::vector<int> handles = {0, 14, 100, 113, 224};
  const SpMat LM = free_block(SpMat(M - L), handles);
  expect_agrees_with_eigen(reordered(LM, amd_order(LM)), 1e-15, 1e-12);
  // The BBW system: Q = L M⁻¹ L (two-ring stencil, condition ~ h⁻⁴).
  const SpMat Q = free_block(SpMat(L * (M.diagonal().cwiseInverse().asDiagonal() * L)), handles);
  expect_agrees_with_eigen(reordered(Q, amd_order(Q)), 1e-14, 1e-9);
}

TEST(SupernodalCholesky, SupernodesOfSeveralSizes) {
  // Dense diagonal blocks of 1, 3, 7 and 20 columns, each coupled to a dense final block of 5:
  // every block is one supernode of its own size (amalgamation has nothing to merge into the
  // separator that its rules allow for the large blocks).
  std::vector<int> blocks = {1, 3, 7, 20};
  const int separator = 5;
  int n = separator;
  for (int b : blocks) n += b;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<Eigen::Triplet<double>> lower;
  int at = 0;
  const int sep0 = n - separator;
  for (int b : blocks) {
    for (int i = 0; i < b; ++i) {
      for (int j = 0; j < i; ++j) lower.emplace_back(at + i, at + j, value(rng));
      for (int s = 0; s < separator; ++s) lower.emplace_back(sep0 + s, at + i, value(rng));
    }
    at += b;
  }
  for (int i = 0; i < separator; ++i)
    for (int j = 0; j < i; ++j) lower.emplace_back(sep0 + i, sep0 + j, value(rng));
  for (int i = 0; i < n; ++i) lower.emplace_back(i, i, 2.0 * n);
  const SpMat A = symmetric(n, lower);
  SupernodalCholesky c;
  ASSERT_TRUE(c.factorize(A));
  const std::multiset<int> sizes = supernode_sizes(c);
  EXPECT_GE(std::set<int>(sizes.begin(), sizes.end()).size(), 3u) << "supernode sizes did not vary";
  EXPECT_LT(c.supernode_count(), n);  // columns were grouped
  expect_agrees_with_eigen(A, 1e-15, 1e-13);

  // The bilaplacian of a larger grid in AMD order also mixes supernode sizes.
  const test_meshes::Mesh mesh = test_meshes::grid_mesh(24, false);
  SpMat L, M;
  cotangent_laplacian(mesh.view(), L);
  mass_matrix(mesh.view(), MassType::kBarycentric, M);
  const SpMat Q = free_block(SpMat(L * (M.diagonal().cwiseInverse().asDiagonal() * L)), {0, 24, 312, 600, 624});
  const SpMat Qo = reordered(Q, amd_order(Q));
  SupernodalCholesky g;
  ASSERT_TRUE(g.factorize(Qo));
  const std::multiset<int> grid_sizes = supernode_sizes(g);
  EXPECT_GE(*grid_sizes.rbegin(), 16) << "no large supernode";
  EXPECT_GE(std::set<int>(grid_sizes.begin(), grid_sizes.end()).size(), 4u);
  expect_agrees_with_eigen(Qo, 1e-14, 1e-9);
}

TEST(SupernodalCholesky, IllConditionedMatchesDenseLlt) {
  // A 1D Laplacian with a small shift, scaled by D = diag(10^(−4..4)) on both sides: condition
  // ~1e21 by scaling and ~1e5 by the Laplacian itself. Cholesky is invariant to the symmetric
  // scaling, so both solvers should still agree to about cond(D⁻¹AD⁻¹)·ε.
  const int n = 200;
  std::vector<Eigen::Triplet<double>> lower;
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = std::pow(10.0, -4 + 8.0 * i / (n - 1));
  for (int i = 0; i < n; ++i) {
    lower.emplace_back(i, i, (2 + 1e-4) * d[i] * d[i]);
    if (i > 0) lower.emplace_back(i, i - 1, -d[i] * d[i - 1]);
  }
  const SpMat A = symmetric(n, lower);
  SupernodalCholesky c;
  ASSERT_TRUE(c.factorize(A));
  const Eigen::MatrixXd dense(A);
  const Eigen::LLT<Eigen::MatrixXd> llt(dense);
  ASSERT_EQ(llt.info(), Eigen::Success);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(n), x = b;
  c.solve(x.data());
  const Eigen::VectorXd reference = llt.solve(b);
  // Compare in the scaled variables D x, where the problem is only as hard as the Laplacian.
  const Eigen::VectorXd sx = d.cwiseProduct(x), sr = d.cwiseProduct(reference);
  EXPECT_LE((sx - sr).lpNorm<Eigen::Infinity>(), 1e-9 * sr.lpNorm<Eigen::Infinity>());
  // Relative residual of the scaled system T (D x) = D⁻¹ b, ‖T‖∞ ≤ 4.0001.
  const Eigen::VectorXd scaled_b = b.cwiseQuotient(d);
  EXPECT_LE((dense * x - b).cwiseQuotient(d).lpNorm<Eigen::Infinity>(),
            1e-14 * (4.0001 * sx.lpNorm<Eigen::Infinity>() + scaled_b.lpNorm<Eigen::Infinity>()));
}

TEST(SupernodalCholesky, ReportsMatricesThatAreNotPositiveDefinite) {
  SupernodalCholesky c;
  // Indefinite 2 by 2 (eigenvalues 3 and −1).
  SpMat A = symmetric(2, {{0, 0, 1.0}, {1, 1, 1.0}, {1, 0, 2.0}});
  EXPECT_FALSE(c.factorize(A));
  // A negative pivot at the very first column.
  EXPECT_FALSE(c.factorize(symmetric(3, {{0, 0, -1.0}, {1, 1, 2.0}, {2, 2, 2.0}, {1, 0, 0.5}})));
  // Zero matrix (singular).
  EXPECT_FALSE(c.factorize(symmetric(2, {{0, 0, 0.0}, {1, 1, 0.0}})));
  // A large sparse one whose only negative eigenvalue is smooth (found late in the elimination):
  // −L_ff shifted below its smallest eigenvalue.
  const test_meshes::Mesh mesh = test_meshes::grid_mesh(12, true);
  SpMat L;
  cotangent_laplacian(mesh.view(), L);
  const SpMat K = free_block(SpMat(-L), {0, 12});
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig((Eigen::MatrixXd(K)));
  const double smallest = eig.eigenvalues()[0];
  ASSERT_GT(smallest, 0);
  SpMat shifted = K;
  for (int i = 0; i < K.rows(); ++i) shifted.coeffRef(i, i) -= 1.5 * smallest;
  const SpMat ordered = reordered(shifted, amd_order(shifted));
  EXPECT_FALSE(c.factorize(ordered));
  // Just above it, the same structure factors, and the object recovers from the failures.
  SpMat positive = K;
  for (int i = 0; i < K.rows(); ++i) positive.coeffRef(i, i) -= 0.5 * smallest;
  expect_agrees_with_eigen(reordered(positive, amd_order(positive)), 1e-13, 1e-8);
  const SpMat spd = reordered(K, amd_order(K));
  EXPECT_TRUE(c.factorize(spd));
  Eigen::VectorXd x = Eigen::VectorXd::Ones(spd.rows());
  c.solve(x.data());
  EXPECT_LE((spd * x - Eigen::VectorXd::Ones(spd.rows())).lpNorm<Eigen::Infinity>(), 1e-10);
}

TEST(SupernodalCholesky, RefactorsMatricesOfChangingSizeAndStructure) {
  // One object, as the active-set solver uses it: factor after factor of different matrices.
  SupernodalCholesky c;
  for (int round = 0; round < 3; ++round)
    for (int n : {50, 400, 7, 120}) {
      const SpMat A = random_spd(n, 8, unsigned(100 * round + n));
      ASSERT_TRUE(c.factorize(A));
      Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 1), x = b;
      c.solve(x.data());
      EXPECT_LE((A * x - b).lpNorm<Eigen::Infinity>(), 1e-13) << n;
    }
}
