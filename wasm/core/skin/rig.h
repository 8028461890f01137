// splinekit — skinning cubic Bézier splines so that they stay splines.
//
// Liu, Jacobson & Gingold, "Skinning Cubic Bézier Splines and Catmull-Clark Subdivision
// Surfaces", SIGGRAPH Asia 2014, §3–§4 (file: papers/skinning-cubic-bezier-splines-and-catmull-clark.txt).
//
// Linear blend skinning s(p) = Σ_i w_i(p) T_i [p; 1] bends the artwork; instead of moving the
// control points by s (which strays from the bent shape), the rig finds control points X whose
// curves are closest to the bent curves, integrated along every curve (eq. 3), weighted by each
// curve's rest length (§4.1), subject to the continuity of every junction (§4):
//
//   minimize  Σ_j ℓ_j ∫ |B_j(t; X) − s(B_j(t; P))|² dt   subject to the junction constraints.
//
// The integrals use S samples per curve (midpoint rule) for both Â and Ŵ_i (the paper's
// footnote), so the identity pose reproduces the input exactly. Anchors are shared between
// consecutive curves, which is C0 by construction; each C1, G1 or angle junction keeps its rest
// relation between the tangent vectors a = P − H_in and b = H_out − P,
//
//   b = ρ R(θ) a        (ρ = |b|/|a|, θ = the turn from a to b, both measured at rest),
//
// a linear constraint (eq. 5 and its angle form) that is eliminated by substitution
// (H_out = P + ρR(θ)(P − H_in)); this is the same minimizer as the paper's Lagrange-multiplier
// system, but the reduced system is symmetric positive definite, so one sparse Cholesky (LDLᵀ)
// factorization serves every pose: X = Σ_i O_i vec(T_i) (§4.1), O precomputed.
//
// Flexible G1 / angle (§4, eq. 6–12) alternates the fixed-ratio form with a fixed-direction form
// (H_in = P − α u, H_out = P + β R(θ) u, α, β > 0 free), refactoring each time; the energy never
// increases (a step that would increase it after clamping α, β is rejected).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <string>
#include <vector>

#include "common/continuity.h"
#include "common/spline_set.h"

namespace splinekit::skin {

struct SkinOptions {
  int samples = 100;              // S, quadrature samples per curve (paper: 100)
  int relax_max_iterations = 20;  // flexible G1/angle: cap on alternating iterations
  double relax_tolerance = 1e-3;  // stop when an iteration lowers the energy by less than this fraction
};

// What relax() did, for tests and the UI.
struct RelaxReport {
  int iterations = 0;
  int rejected = 0;              // steps undone because clamping would have raised the energy
  std::vector<double> energies;  // energy before the first and after every accepted iteration
};

// The deformation methods compared in the paper (§5). The numbers cross to TS (src/skin/rig.ts).
enum class SkinMethod : int {
  kFit = 0,                // this rig's least-squares fit
  kNaiveAll = 1,           // every control point moved by s
  kNaiveInterpolated = 2,  // anchors by s; handles by their anchor's blended transform
  kNaiveJacobian = 3,      // anchors by s; handles by the Jacobian of s at their anchor
};

class SkinRig {
 public:
  // ---- Constructors ---------------------------------------------------------------------------
  // rest: the splines at rest. kinds: one per junction, in junction order (total_junctions(rest)).
  // Returns "" or a message naming the problem; the rig is unusable until it succeeds.
  std::string setup(const SplineSet& rest, const std::vector<Continuity>& kinds, int handle_count,
                    const SkinOptions& options);

  // ---- Weights (set all three, then precompute) -------------------------------------------------
  // Rest positions where weights are needed: the curve samples (#curves·S by 2) ...
  const std::vector<double>& sample_points() const { return sample_points_; }
  // ... and the control points (#points by 2).
  const std::vector<double>& control_points() const { return rest_.points; }
  // Writable weights: at samples (#curves·S by #H), at control points (#points by #H) and their
  // gradients (#points by #H by 2; only the Jacobian baseline reads them).
  std::vector<double>& sample_weights() { return sample_weights_; }
  std::vector<double>& point_weights() { return point_weights_; }
  std::vector<double>& point_gradients() { return point_gradients_; }
  // Shepard weights for handles at `handles` (#H by 2), filling all three arrays.
  void use_shepard(const double* handles, double power);

  // Builds Ŵ, the system, its factorization and O. Returns "" or a message.
  std::string precompute();

  // ---- Queries (per frame; no allocation) -----------------------------------------------------
  // transforms: #H by 6, each the SVG matrix (a b c d e f): x' = a x + c y + e, y' = b x + d y + f.
  // Writes the fitted control points (#points by 2) and returns them.
  const double* update(const double* transforms);
  const std::vector<double>& points() const { return points_; }

  // A baseline's control points for the same transforms (allocation-free after the first call).
  const double* baseline(SkinMethod method, const double* transforms);

  // Flexible G1/angle from the rigid fit for `transforms`; updates points().
  RelaxReport relax(const double* transforms);

  // Integrated squared distance of `points` (#points by 2) to the target: per curve the mean over
  // the samples of |B_j(t) − s(t)|² into per_curve (#curves), and returns Σ_j ℓ_j · per_curve_j.
  double error(const double* points, const double* transforms, double* per_curve) const;

  // Residual of every constraint of the rigid fit at `points`: max |b − ρR(θ)a| over constrained
  // junctions (0 when there are none).
  double constraint_residual(const double* points) const;

  // ---- Counters --------------------------------------------------------------------------------
  int curve_count() const { return int(curves_.size()); }
  int handle_count() const { return handles_; }
  int constrained_count() const { return int(junctions_.size()); }
  double total_length() const { return total_length_; }
  double energy(const double* points, const double* transforms) const;  // the objective (up to a constant)

 private:
  struct Junction {
    int in, anchor, out;  // point indices of H_in, P, H_out
    Continuity kind;
    double ratio, angle;  // rest ρ and θ
  };
  enum class Form { kRatio, kDirection };

  void build_rhs(const double* transforms, Eigen::VectorXd& rhs) const;
  // XᵀHX − 2 X·rhs: the energy up to a constant.
  double quadratic_energy(const double* X, const Eigen::VectorXd& rhs) const;
  // The substitution X = S y for the rigid constraints (Form::kRatio, current = null: rest ρ) or
  // for a relax step (Form::kDirection / Ratio with the current ρ and directions of `current`).
  Eigen::SparseMatrix<double> substitution(Form form, const double* current) const;

  SkinOptions options_;
  SplineSet rest_;
  int handles_ = 0;
  std::vector<std::array<int, 4>> curves_;  // point indices of each cubic
  std::vector<double> lengths_;             // ℓ_j
  double total_length_ = 0;
  std::vector<Junction> junctions_;  // constrained junctions (C1, G1, angle)
  std::vector<int> lone_points_;     // splines with no segment: moved by s itself

  std::vector<double> sample_points_, sample_weights_, point_weights_, point_gradients_;
  Eigen::MatrixXd bernstein_;            // 4 by S, b(t_s)
  Eigen::SparseMatrix<double> hessian_;  // 2N by 2N: Σ ℓ_j Â ⊗ I2 (+ lone points)
  Eigen::MatrixXd wide_;                 // 2N by 6H: rhs = wide_ · vec(T) (Ŵ assembled per point)
  Eigen::MatrixXd O_;                    // 2N by 6H
  std::vector<double> points_, baseline_;
  bool ready_ = false;
};

}  // namespace splinekit::skin
