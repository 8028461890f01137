#include "box_qp.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace splinekit::skin {

namespace {

// Which bound holds a variable (stored as char per variable).
enum class Bound : char { kFree = 0, kLower = 1, kUpper = 2 };

// Rings (in the graph of Q) of the active set released together with a variable whose
// multiplier says "release" (see solve_box_qp).
constexpr int kInitialSpread = 4;

}  // namespace

// Minimizes ½ xᵀQx + cᵀx subject to 0 ≤ x ≤ 1 by the primal-dual active-set method (PDAS), from
// x (the unconstrained minimizer). With g = Qx + c, the KKT conditions are: g_i = 0 where
// 0 < x_i < 1, g_i ≥ 0 where x_i = 0, g_i ≤ 0 where x_i = 1. Each iteration (1) moves free
// variables that violate a bound onto it and releases bound variables whose multiplier g_i has
// the wrong sign, (2) solves Q_II x_I = −(c_I + Q_IA x_A) with the active ones fixed. It stops
// when the sets no longer change, which is exactly the KKT point (up to the tolerances).
//
// Release acceleration: the multipliers of a biharmonic obstacle problem concentrate on the rim
// of the active set, so plain PDAS learns only about that rim and shrinks an oversized active
// set one ring per iteration. Here a release also frees `spread` rings of the same bound around
// it; a variable freed that way which comes back violated halves `spread` (down to 0 = plain
// PDAS, whose fixed points are the same). This cuts the iterations about in half.
//
// Anti-cycling: Q is not an M-matrix, so PDAS can cycle (a few rim variables released for their
// multipliers, then re-bound because they dip a hair below 0). Once a state repeats, spreading
// stops and a variable that has been released before stays at its bound when asked to leave it
// again, which makes the method terminate; such `pinned` variables keep a wrong-signed
// multiplier, at a weight error of the size of their dip (below 1e-10 where observed).
//
// `multiplier_tolerance`: per-variable tolerance on wrong-signed multipliers (BbwOptions in
// weights.h explains its scale).
BoxQpReport solve_box_qp(const Eigen::SparseMatrix<double>& Q, const Eigen::VectorXd& c,
                         const Eigen::VectorXd& multiplier_tolerance, const BoxQpOptions& options, SubsetSolver& solver,
                         Eigen::VectorXd& x) {
  BoxQpReport report;
  const int n = int(c.size());
  const double tol_x = options.bound_tolerance;
  std::vector<Bound> bound(size_t(n), Bound::kFree), next(size_t(n), Bound::kFree);
  std::vector<char> keep(size_t(n), 1);
  std::vector<char> spread_freed(size_t(n), 0), released(size_t(n), 0), pinned(size_t(n), 0);
  std::vector<int> ring, next_ring;
  std::vector<uint64_t> seen;  // hashes of the active sets so far
  Eigen::VectorXd g = Q * x + c, fixed(n), rhs(n);
  int spread = kInitialSpread;
  bool cycling = false;
  for (;;) {
    for (int i = 0; i < n; ++i)
      if (spread_freed[i] && (x[i] < -tol_x || x[i] > 1 + tol_x)) {
        spread /= 2;
        break;
      }
    // The plain PDAS update.
    ring.clear();
    for (int i = 0; i < n; ++i) {
      Bound b = bound[i];
      if (b == Bound::kFree) {
        b = x[i] < -tol_x ? Bound::kLower : x[i] > 1 + tol_x ? Bound::kUpper : Bound::kFree;
      } else if ((b == Bound::kLower && g[i] < -multiplier_tolerance[i]) ||
                 (b == Bound::kUpper && g[i] > multiplier_tolerance[i])) {
        if (!cycling || !released[i])
          b = Bound::kFree;
        else if (!pinned[i])
          pinned[i] = 1, ++report.pinned;
      }
      next[i] = b;
      if (bound[i] != Bound::kFree && b == Bound::kFree) ring.push_back(i);
    }
    // Spread the releases over neighbours held at the same bound.
    std::fill(spread_freed.begin(), spread_freed.end(), 0);
    for (int r = 0; r < spread && !ring.empty(); ++r) {
      next_ring.clear();
      for (int i : ring)
        for (Eigen::SparseMatrix<double>::InnerIterator it(Q, i); it; ++it) {
          const int j = int(it.row());
          if (next[j] != Bound::kFree && next[j] == bound[j] && bound[j] == bound[i]) {
            next[j] = Bound::kFree;
            spread_freed[j] = 1;
            next_ring.push_back(j);
          }
        }
      ring.swap(next_ring);
    }
    if (next == bound) {
      report.converged = true;
      break;
    }
    for (int i = 0; i < n; ++i) released[i] |= bound[i] != Bound::kFree && next[i] == Bound::kFree;
    bound.swap(next);
    // Each iteration is a function of (active set, spread, spread-freed variables), so a repeated
    // state (FNV-1a hash) is a cycle.
    uint64_t hash = 1469598103934665603ull;
    auto mix = [&hash](uint64_t byte) { hash = (hash ^ byte) * 1099511628211ull; };
    for (int i = 0; i < n; ++i) mix(uint64_t(uint8_t(bound[i])) | uint64_t(spread_freed[i]) << 2);
    mix(uint64_t(spread));
    if (std::find(seen.begin(), seen.end(), hash) != seen.end()) cycling = true, spread = 0;
    seen.push_back(hash);
    if (report.solves >= options.max_iterations) break;
    for (int i = 0; i < n; ++i) {
      keep[i] = bound[i] == Bound::kFree;
      fixed[i] = bound[i] == Bound::kUpper ? 1.0 : 0.0;
    }
    if (!solver.factorize(keep)) {
      report.error = "internal: the bilaplacian of the free vertices is not numerically positive definite";
      break;
    }
    rhs = -(c + Q * fixed);
    x = fixed;
    solver.solve(rhs, x);
    g = Q * x + c;
    ++report.solves;
  }
  x = x.cwiseMax(0.0).cwiseMin(1.0);
  return report;
}

}  // namespace splinekit::skin
