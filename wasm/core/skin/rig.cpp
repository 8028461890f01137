#include "rig.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "common/bezier.h"
#include "common/geometry.h"
#include "shepard.h"

namespace splinekit::skin {

namespace {

Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

bool finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Setup
// ---------------------------------------------------------------------------------------------

std::string SkinRig::setup(const SplineSet& rest, const std::vector<Continuity>& kinds, int handle_count,
                           const SkinOptions& options) {
  ready_ = false;
  if (std::string e = validate(rest); !e.empty()) return e;
  if (int(kinds.size()) != total_junctions(rest))
    return "expected " + std::to_string(total_junctions(rest)) + " continuity tags, got " +
           std::to_string(kinds.size());
  if (handle_count < 1) return "a rig needs at least one handle";
  if (options.samples < 4 || options.samples > 10000) return "samples per curve must be in [4, 10000]";
  options_ = options;
  rest_ = rest;
  handles_ = handle_count;
  curves_.clear();
  lengths_.clear();
  junctions_.clear();
  lone_points_.clear();

  double seg[8];
  const int S = options_.samples;
  for (int s = 0; s < rest_.spline_count(); ++s) {
    const bool closed = rest_.closed[s] != 0;
    const int base = rest_.start[s], count = rest_.count[s];
    if (count == 1) lone_points_.push_back(base);
    for (int k = 0; k < spline_segment_count(count, closed); ++k) {
      std::array<int, 4> c;
      for (int a = 0; a < 4; ++a) c[a] = base + (3 * k + a) % count;
      curves_.push_back(c);
      spline_segment(rest_.spline_points(s), count, closed, k, seg);
      lengths_.push_back(bezier_arc_length(seg, 0, 1, 1e-9));
    }
  }
  // ℓ_j weights the energy of curve j; a zero-length curve still needs some weight to keep its
  // points determined, so lengths are clamped to a small fraction of the mean.
  total_length_ = 0;
  for (double l : lengths_) total_length_ += l;
  const double floor = lengths_.empty() ? 1.0 : std::max(1e-6 * total_length_ / lengths_.size(), 1e-300);
  for (double& l : lengths_) l = std::max(l, floor);

  // Junction constraints, in junction order.
  int j = 0;
  for (int s = 0; s < rest_.spline_count(); ++s) {
    const bool closed = rest_.closed[s] != 0;
    const int base = rest_.start[s], count = rest_.count[s];
    for (int q = 0; q < spline_junction_count(count, closed); ++q, ++j) {
      const Continuity kind = kinds[j];
      if (kind != Continuity::kC1 && kind != Continuity::kG1 && kind != Continuity::kAngle) continue;
      const int anchor = closed ? 3 * q : 3 * (q + 1);
      Junction c{base + (anchor + count - 1) % count, base + anchor, base + (anchor + 1) % count, kind, 1.0, 0.0};
      const Vec2 a = vec2_at(rest_.points.data(), c.anchor) - vec2_at(rest_.points.data(), c.in);
      const Vec2 b = vec2_at(rest_.points.data(), c.out) - vec2_at(rest_.points.data(), c.anchor);
      if (a.norm() <= 1e-12 * (1 + total_length_) || b.norm() <= 1e-12 * (1 + total_length_))
        continue;  // no tangent to keep
      c.ratio = b.norm() / a.norm();
      c.angle = std::atan2(cross(a, b), a.dot(b));
      junctions_.push_back(c);
    }
  }

  // Quadrature: midpoint rule, t_s = (s + 1/2) / S, for Â and Ŵ alike.
  bernstein_.resize(4, S);
  for (int s = 0; s < S; ++s) bernstein_.col(s) = bernstein((s + 0.5) / S);
  sample_points_.assign(2 * curves_.size() * size_t(S), 0.0);
  for (size_t c = 0; c < curves_.size(); ++c)
    for (int s = 0; s < S; ++s) {
      Vec2 p = Vec2::Zero();
      for (int a = 0; a < 4; ++a) p += bernstein_(a, s) * vec2_at(rest_.points.data(), curves_[c][a]);
      sample_points_[2 * (c * S + s)] = p.x();
      sample_points_[2 * (c * S + s) + 1] = p.y();
    }
  sample_weights_.assign(curves_.size() * size_t(S) * handles_, 0.0);
  point_weights_.assign(size_t(rest_.point_count()) * handles_, 0.0);
  point_gradients_.assign(size_t(rest_.point_count()) * handles_ * 2, 0.0);
  points_.assign(rest_.points.size(), 0.0);
  baseline_.assign(rest_.points.size(), 0.0);
  return {};
}

void SkinRig::use_shepard(const double* handles, double power) {
  const int S = options_.samples;
  shepard_weights(handles, handles_, sample_points_.data(), int(curves_.size()) * S, power, sample_weights_.data());
  shepard_weights(handles, handles_, rest_.points.data(), rest_.point_count(), power, point_weights_.data());
  shepard_gradients(handles, handles_, rest_.points.data(), rest_.point_count(), power, point_gradients_.data());
}

// ---------------------------------------------------------------------------------------------
// Precompute
// ---------------------------------------------------------------------------------------------

std::string SkinRig::precompute() {
  ready_ = false;
  if (!finite(sample_weights_) || !finite(point_weights_) || !finite(point_gradients_))
    return "skinning weights contain a non-finite value";
  const int N = rest_.point_count(), S = options_.samples, H = handles_;
  const Eigen::Matrix4d gram = bernstein_ * bernstein_.transpose() / S;  // numerical Â

  // Hessian Σ_j ℓ_j Â ⊗ I2 and Ŵ assembled per point: rhs = wide_ · vec(T), with vec(T_i) =
  // (a b c d e f) at columns 6i..6i+5: x' = a x + c y + e, y' = b x + d y + f.
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(curves_.size() * 32 + lone_points_.size() * 2);
  wide_.setZero(2 * N, 6 * H);
  Eigen::MatrixXd acc(4 * H, 3);  // per curve: Σ_s m_s[a] w_i(p_s) [p_s; 1]
  for (size_t c = 0; c < curves_.size(); ++c) {
    const double l = lengths_[c];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int r = 0; r < 2; ++r) triplets.emplace_back(2 * curves_[c][a] + r, 2 * curves_[c][b] + r, l * gram(a, b));
    acc.setZero();
    for (int s = 0; s < S; ++s) {
      const size_t sample = c * S + s;
      const double px = sample_points_[2 * sample], py = sample_points_[2 * sample + 1];
      const double* w = sample_weights_.data() + sample * H;
      for (int i = 0; i < H; ++i) {
        if (w[i] == 0.0) continue;
        for (int a = 0; a < 4; ++a) {
          const double f = bernstein_(a, s) * w[i];
          acc(4 * i + a, 0) += f * px;
          acc(4 * i + a, 1) += f * py;
          acc(4 * i + a, 2) += f;
        }
      }
    }
    acc *= l / S;
    for (int a = 0; a < 4; ++a) {
      const int k = curves_[c][a];
      for (int i = 0; i < H; ++i) {
        const double gx = acc(4 * i + a, 0), gy = acc(4 * i + a, 1), g1 = acc(4 * i + a, 2);
        wide_(2 * k, 6 * i + 0) += gx, wide_(2 * k, 6 * i + 2) += gy, wide_(2 * k, 6 * i + 4) += g1;
        wide_(2 * k + 1, 6 * i + 1) += gx, wide_(2 * k + 1, 6 * i + 3) += gy, wide_(2 * k + 1, 6 * i + 5) += g1;
      }
    }
  }
  // A lone point (a spline with no segment) is simply moved by s: unit energy around its target.
  for (int k : lone_points_) {
    for (int r = 0; r < 2; ++r) triplets.emplace_back(2 * k + r, 2 * k + r, 1.0);
    const double x = rest_.points[2 * k], y = rest_.points[2 * k + 1];
    for (int i = 0; i < H; ++i) {
      const double w = point_weights_[size_t(k) * H + i];
      wide_(2 * k, 6 * i + 0) += w * x, wide_(2 * k, 6 * i + 2) += w * y, wide_(2 * k, 6 * i + 4) += w;
      wide_(2 * k + 1, 6 * i + 1) += w * x, wide_(2 * k + 1, 6 * i + 3) += w * y, wide_(2 * k + 1, 6 * i + 5) += w;
    }
  }
  hessian_.resize(2 * N, 2 * N);
  hessian_.setFromTriplets(triplets.begin(), triplets.end());

  // Reduced system SᵀHS y = Sᵀ rhs, X = S y: one factorization for every pose.
  const Eigen::SparseMatrix<double> sub = substitution(Form::kRatio, nullptr);
  const Eigen::SparseMatrix<double> reduced = sub.transpose() * hessian_ * sub;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(reduced);
  if (solver.info() != Eigen::Success) return "the skinning system could not be factorized (degenerate curves?)";
  const Eigen::MatrixXd y = solver.solve(Eigen::MatrixXd(sub.transpose() * wide_));
  if (solver.info() != Eigen::Success || !y.allFinite()) return "the skinning system could not be solved";
  O_ = sub * y;
  ready_ = true;
  return {};
}

Eigen::SparseMatrix<double> SkinRig::substitution(Form form, const double* current) const {
  const int N = rest_.point_count();
  // Which points are expressed through others: every constrained H_out; in the direction form
  // also the H_in of flexible junctions (G1, angle), which get scalars α, β instead.
  std::vector<int> role(N, -1);  // -1 free; else index into junctions_ (H_out, or H_in when flexible)
  for (size_t j = 0; j < junctions_.size(); ++j) {
    role[junctions_[j].out] = int(j);
    if (form == Form::kDirection && junctions_[j].kind != Continuity::kC1) role[junctions_[j].in] = int(j);
  }
  std::vector<int> var(N, -1);
  int vars = 0;
  for (int k = 0; k < N; ++k)
    if (role[k] < 0) var[k] = vars, vars += 2;
  std::vector<int> scalar(junctions_.size(), -1);
  if (form == Form::kDirection)
    for (size_t j = 0; j < junctions_.size(); ++j)
      if (junctions_[j].kind != Continuity::kC1) scalar[j] = vars, vars += 2;

  std::vector<Eigen::Triplet<double>> t;
  t.reserve(2 * N + 8 * junctions_.size());
  for (int k = 0; k < N; ++k)
    if (var[k] >= 0) t.emplace_back(2 * k, var[k], 1.0), t.emplace_back(2 * k + 1, var[k] + 1, 1.0);
  for (size_t j = 0; j < junctions_.size(); ++j) {
    const Junction& c = junctions_[j];
    const Eigen::Matrix2d R = rotation(c.angle);
    if (scalar[j] >= 0) {
      // H_in = P − α u, H_out = P + β R u, u the current unit direction of a = P − H_in.
      Vec2 u = vec2_at(current, c.anchor) - vec2_at(current, c.in);
      if (u.norm() <= 1e-300) u = vec2_at(rest_.points.data(), c.anchor) - vec2_at(rest_.points.data(), c.in);
      u.normalize();
      const Vec2 v = R * u;
      for (int r = 0; r < 2; ++r) {
        t.emplace_back(2 * c.in + r, var[c.anchor] + r, 1.0);
        t.emplace_back(2 * c.in + r, scalar[j], -u[r]);
        t.emplace_back(2 * c.out + r, var[c.anchor] + r, 1.0);
        t.emplace_back(2 * c.out + r, scalar[j] + 1, v[r]);
      }
      continue;
    }
    // H_out = P + ρR(P − H_in): rest ρ, or the current one for a flexible junction mid-relax.
    double rho = c.ratio;
    if (current && c.kind != Continuity::kC1) {
      const double la = (vec2_at(current, c.anchor) - vec2_at(current, c.in)).norm();
      const double lb = (vec2_at(current, c.out) - vec2_at(current, c.anchor)).norm();
      if (la > 1e-300) rho = lb / la;
    }
    const Eigen::Matrix2d M = rho * R;
    for (int r = 0; r < 2; ++r)
      for (int q = 0; q < 2; ++q) {
        t.emplace_back(2 * c.out + r, var[c.anchor] + q, (r == q ? 1.0 : 0.0) + M(r, q));
        t.emplace_back(2 * c.out + r, var[c.in] + q, -M(r, q));
      }
  }
  Eigen::SparseMatrix<double> sub(2 * N, vars);
  sub.setFromTriplets(t.begin(), t.end());
  return sub;
}

// ---------------------------------------------------------------------------------------------
// Per frame
// ---------------------------------------------------------------------------------------------

const double* SkinRig::update(const double* transforms) {
  Eigen::Map<Eigen::VectorXd> out(points_.data(), Eigen::Index(points_.size()));
  const Eigen::Map<const Eigen::VectorXd> tau(transforms, 6 * handles_);
  out.noalias() = O_ * tau;
  return points_.data();
}

void SkinRig::build_rhs(const double* transforms, Eigen::VectorXd& rhs) const {
  rhs.noalias() = wide_ * Eigen::Map<const Eigen::VectorXd>(transforms, 6 * handles_);
}

const double* SkinRig::baseline(SkinMethod method, const double* T) {
  if (method == SkinMethod::kFit) return update(T);
  const int N = rest_.point_count(), H = handles_;
  const double* P = rest_.points.data();
  // s at p with the weights of point k: Σ_i w_i T_i [p; 1].
  auto blend = [&](int k, double x, double y, double* out) {
    out[0] = out[1] = 0;
    for (int i = 0; i < H; ++i) {
      const double w = point_weights_[size_t(k) * H + i];
      const double* t = T + 6 * i;
      out[0] += w * (t[0] * x + t[2] * y + t[4]);
      out[1] += w * (t[1] * x + t[3] * y + t[5]);
    }
  };
  for (int k = 0; k < N; ++k) blend(k, P[2 * k], P[2 * k + 1], &baseline_[2 * k]);
  if (method == SkinMethod::kNaiveAll) return baseline_.data();
  for (int s = 0; s < rest_.spline_count(); ++s) {
    const int base = rest_.start[s], count = rest_.count[s];
    for (int l = 0; l < count; ++l) {
      if (l % 3 == 0) continue;
      const int k = base + l;
      const int anchor = base + (l % 3 == 1 ? l - 1 : (l + 1) % count);
      const double ax = P[2 * anchor], ay = P[2 * anchor + 1];
      if (method == SkinMethod::kNaiveInterpolated) {
        blend(anchor, P[2 * k], P[2 * k + 1], &baseline_[2 * k]);
        continue;
      }
      // Jacobian of s at the anchor: J = Σ_i w_i L_i + (T_i [A; 1]) ∇w_iᵀ.
      double J[4] = {0, 0, 0, 0};
      for (int i = 0; i < H; ++i) {
        const double w = point_weights_[size_t(anchor) * H + i];
        const double* g = &point_gradients_[(size_t(anchor) * H + i) * 2];
        const double* t = T + 6 * i;
        const double sx = t[0] * ax + t[2] * ay + t[4], sy = t[1] * ax + t[3] * ay + t[5];
        J[0] += w * t[0] + sx * g[0], J[1] += w * t[2] + sx * g[1];
        J[2] += w * t[1] + sy * g[0], J[3] += w * t[3] + sy * g[1];
      }
      const double dx = P[2 * k] - ax, dy = P[2 * k + 1] - ay;
      baseline_[2 * k] = baseline_[2 * anchor] + J[0] * dx + J[1] * dy;
      baseline_[2 * k + 1] = baseline_[2 * anchor + 1] + J[2] * dx + J[3] * dy;
    }
  }
  return baseline_.data();
}

double SkinRig::error(const double* X, const double* T, double* per_curve) const {
  const int S = options_.samples, H = handles_;
  double total = 0;
  for (size_t c = 0; c < curves_.size(); ++c) {
    double sum = 0;
    for (int s = 0; s < S; ++s) {
      const size_t sample = c * S + s;
      double bx = 0, by = 0;
      for (int a = 0; a < 4; ++a)
        bx += bernstein_(a, s) * X[2 * curves_[c][a]], by += bernstein_(a, s) * X[2 * curves_[c][a] + 1];
      const double px = sample_points_[2 * sample], py = sample_points_[2 * sample + 1];
      double tx = 0, ty = 0;
      for (int i = 0; i < H; ++i) {
        const double w = sample_weights_[sample * H + i];
        const double* t = T + 6 * i;
        tx += w * (t[0] * px + t[2] * py + t[4]);
        ty += w * (t[1] * px + t[3] * py + t[5]);
      }
      sum += (bx - tx) * (bx - tx) + (by - ty) * (by - ty);
    }
    const double mean = sum / S;
    if (per_curve) per_curve[c] = mean;
    total += lengths_[c] * mean;
  }
  return total;
}

double SkinRig::energy(const double* X, const double* T) const { return error(X, T, nullptr); }

double SkinRig::constraint_residual(const double* X) const {
  double worst = 0;
  for (const Junction& c : junctions_) {
    const Vec2 a = vec2_at(X, c.anchor) - vec2_at(X, c.in), b = vec2_at(X, c.out) - vec2_at(X, c.anchor);
    worst = std::max(worst, (b - c.ratio * rotation(c.angle) * a).norm());
  }
  return worst;
}

// ---------------------------------------------------------------------------------------------
// Flexible G1 / angle
// ---------------------------------------------------------------------------------------------

RelaxReport SkinRig::relax(const double* T) {
  RelaxReport report;
  update(T);
  int flexible = 0;
  for (const Junction& c : junctions_) flexible += c.kind != Continuity::kC1;
  // The energy as a quadratic form, E(X) = XᵀHX − 2 X·rhs + c, c = Σ ℓ_j ∫|s|²: cheap per step.
  Eigen::VectorXd rhs(points_.size());
  build_rhs(T, rhs);
  const double c = energy(points_.data(), T) - quadratic_energy(points_.data(), rhs);
  report.energies.push_back(quadratic_energy(points_.data(), rhs) + c);
  if (flexible == 0) return report;

  std::vector<double> trial(points_.size());
  const double eps = 1e-9 * std::max(total_length_, 1e-300);
  // One symbolic analysis per form: the pattern of SᵀHS does not change between iterations.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solvers[2];
  Eigen::SparseMatrix<double> patterns[2];
  int streak = 0;
  for (int it = 0; it < options_.relax_max_iterations; ++it) {
    const int f = it % 2;
    const Form form = f == 0 ? Form::kDirection : Form::kRatio;
    const Eigen::SparseMatrix<double> sub = substitution(form, points_.data());
    Eigen::SparseMatrix<double> A = sub.transpose() * hessian_ * sub;
    A.makeCompressed();
    const bool same =
        patterns[f].rows() == A.rows() && patterns[f].nonZeros() == A.nonZeros() &&
        std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1, patterns[f].outerIndexPtr()) &&
        std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), patterns[f].innerIndexPtr());
    if (!same) {
      solvers[f].analyzePattern(A);
      patterns[f] = A;
    }
    solvers[f].factorize(A);
    if (solvers[f].info() != Eigen::Success) break;
    Eigen::VectorXd y = solvers[f].solve(sub.transpose() * rhs);
    if (solvers[f].info() != Eigen::Success || !y.allFinite()) break;
    // α, β > 0 (clamped, as in the paper): a handle may not flip through its anchor. They are the
    // last 2·flexible unknowns of the direction form.
    if (form == Form::kDirection)
      for (Eigen::Index k = y.size() - 2 * flexible; k < y.size(); ++k) y[k] = std::max(y[k], eps);
    Eigen::Map<Eigen::VectorXd>(trial.data(), Eigen::Index(trial.size())) = sub * y;
    const double e = quadratic_energy(trial.data(), rhs) + c;
    const double previous = report.energies.back();
    if (e > previous + 1e-12 * std::abs(previous)) {
      ++report.rejected;
      if (++streak >= 2) break;
      continue;
    }
    streak = 0;
    points_.swap(trial);
    report.energies.push_back(e);
    ++report.iterations;
    if (previous - e <= options_.relax_tolerance * previous) break;
  }
  return report;
}

double SkinRig::quadratic_energy(const double* X, const Eigen::VectorXd& rhs) const {
  const Eigen::Map<const Eigen::VectorXd> x(X, rhs.size());
  return x.dot(hessian_ * x) - 2 * x.dot(rhs);
}

}  // namespace splinekit::skin
