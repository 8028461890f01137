// The box-constrained QP of one BBW handle on its own: a closed form (diagonal Q) and the exact
// optimum of small random problems found by enumerating every active set.
#include "skin/box_qp.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace splinekit::skin;
using SpMat = Eigen::SparseMatrix<double>;

namespace {

// Random sparse SPD (strictly diagonally dominant), n by n, both triangles.
SpMat random_spd(int n, double density, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1, 1), coin(0, 1);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (coin(rng) < density) A(i, j) = A(j, i) = value(rng);
  for (int i = 0; i < n; ++i) A(i, i) = A.row(i).cwiseAbs().sum() + 0.5;
  return A.sparseView();
}

double objective(const SpMat& Q, const Eigen::VectorXd& c, const Eigen::VectorXd& x) {
  return 0.5 * x.dot(Q * x) + c.dot(x);
}

// The exact minimizer by brute force: for each of the 3^n assignments (at 0, at 1, free) solve
// the free block densely; the best feasible one is the optimum of the strictly convex QP.
Eigen::VectorXd enumerate_optimum(const SpMat& Q, const Eigen::VectorXd& c) {
  const int n = int(c.size());
  const Eigen::MatrixXd D(Q);
  int total = 1;
  for (int i = 0; i < n; ++i) total *= 3;
  Eigen::VectorXd best;
  double best_value = INFINITY;
  for (int code = 0; code < total; ++code) {
    std::vector<int> state(n), free;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    for (int i = 0, k = code; i < n; ++i, k /= 3) {
      state[i] = k % 3;
      if (state[i] == 1) x[i] = 1;
      if (state[i] == 2) free.push_back(i);
    }
    if (!free.empty()) {
      const int m = int(free.size());
      Eigen::MatrixXd A(m, m);
      Eigen::VectorXd r(m);
      for (int a = 0; a < m; ++a) {
        r[a] = -c[free[a]] - D.row(free[a]).dot(x);
        for (int b = 0; b < m; ++b) A(a, b) = D(free[a], free[b]);
      }
      const Eigen::VectorXd y = A.llt().solve(r);
      bool feasible = true;
      for (int a = 0; a < m; ++a) {
        feasible &= y[a] >= -1e-12 && y[a] <= 1 + 1e-12;
        x[free[a]] = y[a];
      }
      if (!feasible) continue;
    }
    const double v = objective(Q, c, x);
    if (v < best_value) best_value = v, best = x;
  }
  return best;
}

Eigen::VectorXd unconstrained(const SpMat& Q, const Eigen::VectorXd& c) { return Eigen::MatrixXd(Q).llt().solve(-c); }

}  // namespace

TEST(BoxQp, DiagonalQuadraticIsTheClampedUnconstrainedMinimizer) {
  const int n = 9;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd c(n), expected(n);
  for (int i = 0; i < n; ++i) {
    const double q = 1 + i, target = -1.0 + 0.375 * i;  // from −1 to 2: below, inside and above [0, 1]
    t.emplace_back(i, i, q);
    c[i] = -q * target;
    expected[i] = std::clamp(target, 0.0, 1.0);
  }
  SpMat Q(n, n);
  Q.setFromTriplets(t.begin(), t.end());
  SubsetSolver solver(Q);
  Eigen::VectorXd x = unconstrained(Q, c);
  const BoxQpReport report = solve_box_qp(Q, c, Eigen::VectorXd::Zero(n), BoxQpOptions{}, solver, x);
  EXPECT_TRUE(report.error.empty());
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.pinned, 0);
  EXPECT_EQ(report.solves, 2);  // the unconstrained solve, then one with the right active set
  for (int i = 0; i < n; ++i) EXPECT_NEAR(x[i], expected[i], 1e-15) << i;
}

TEST(BoxQp, RandomProblemsReachTheEnumeratedOptimum) {
  int bound_seen = 0, free_seen = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const int n = 8;
    const SpMat Q = random_spd(n, 0.5, seed);
    std::mt19937 rng(seed + 100);
    std::uniform_real_distribution<double> value(-4, 3);
    Eigen::VectorXd c(n);
    for (int i = 0; i < n; ++i) c[i] = value(rng);
    const Eigen::VectorXd exact = enumerate_optimum(Q, c);
    ASSERT_EQ(exact.size(), n);

    SubsetSolver solver(Q);
    Eigen::VectorXd x = unconstrained(Q, c);
    BoxQpOptions options;
    options.bound_tolerance = 1e-12;
    const BoxQpReport report = solve_box_qp(Q, c, Eigen::VectorXd::Zero(n), options, solver, x);
    ASSERT_TRUE(report.error.empty()) << seed;
    EXPECT_TRUE(report.converged) << seed;
    EXPECT_EQ(report.pinned, 0) << seed;
    EXPECT_LE((x - exact).lpNorm<Eigen::Infinity>(), 1e-12) << seed;
    for (int i = 0; i < n; ++i) (exact[i] == 0 || exact[i] == 1 ? bound_seen : free_seen) += 1;
  }
  // The problems exercised both kinds of variables.
  EXPECT_GT(bound_seen, 10);
  EXPECT_GT(free_seen, 10);
}

TEST(BoxQp, IterationCapLeavesTheClampedLastIterate) {
  const SpMat Q = random_spd(8, 0.5, 3);
  Eigen::VectorXd c(8);
  c << -5, 4, -1, 0.5, -3, 2, 1, -0.2;
  SubsetSolver solver(Q);
  const Eigen::VectorXd x0 = unconstrained(Q, c);
  ASSERT_TRUE((x0.array() < 0).any() || (x0.array() > 1).any());  // the cap matters
  Eigen::VectorXd x = x0;
  BoxQpOptions options;
  options.max_iterations = 1;
  const BoxQpReport report = solve_box_qp(Q, c, Eigen::VectorXd::Zero(8), options, solver, x);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.solves, 1);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(x[i], std::clamp(x0[i], 0.0, 1.0)) << i;
}
