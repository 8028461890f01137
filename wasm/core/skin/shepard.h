// splinekit — Shepard (inverse distance) skinning weights with analytic gradients.
//
// w_i(p) = |p - h_i|^-k / sum_j |p - h_j|^-k  (k = power, 2 by default), w_i(h_i) = 1.
// Used by Liu, Jacobson & Gingold 2014 (§5) for their largest examples: cheap, smooth away from
// the handles, and differentiable, which the Jacobian baseline needs.
#pragma once

namespace splinekit::skin {

// Weights of `handle_count` handles (handles: #H by 2, flat x,y) at `point_count` points
// (points: #P by 2) into out (#P by #H, row-major). power > 0.
void shepard_weights(const double* handles, int handle_count, const double* points, int point_count, double power,
                     double* out);

// The same weights for points and handles of `dim` coordinates each (handles: #H by dim, points:
// #P by dim, out: #P by #H row-major); shepard_weights is dim = 2. The 3D skinning rig
// (skin3d/rig.h) evaluates them at the refined surface's vertices.
void shepard_weights_nd(const double* handles, int handle_count, const double* points, int point_count, int dim,
                        double power, double* out);

// Gradients ∇w_i at the points into out (#P by #H by 2, row-major: out[(p*H + i)*2 + axis]).
// At a handle the gradient is taken as its limit for power > 1, which is zero.
void shepard_gradients(const double* handles, int handle_count, const double* points, int point_count, double power,
                       double* out);

}  // namespace splinekit::skin
