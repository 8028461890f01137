// splinekit — cubic Bézier kernels.
//
// Every capability builds on these: a cubic segment is 8 doubles (x0 y0 x1 y1 x2 y2 x3 y3),
// a spline is a flat array of control points (3n+1 open, 3n closed). Kernels are free
// functions over flat arrays (no ownership, no allocation) so the same code runs natively
// under GoogleTest and in WebAssembly on the wasm heap.
#pragma once

#include <Eigen/Core>
#include <array>

#include "geometry.h"

namespace splinekit {

// ---------------------------------------------------------------------------------------------
// Bernstein basis
// ---------------------------------------------------------------------------------------------

// The four cubic Bernstein polynomials b_i(t) = C(3,i) t^i (1-t)^(3-i).
Eigen::Vector4d bernstein(double t);

// Exact Gram matrix of the cubic Bernstein basis, Â = ∫₀¹ b(t) b(t)ᵀ dt,
// Â_ij = C(3,i) C(3,j) / (7 C(6,i+j)). This is the Â of Liu, Jacobson & Gingold 2014 (§3).
Eigen::Matrix4d bernstein_gram();

// ---------------------------------------------------------------------------------------------
// One cubic segment: c points at 8 doubles
// ---------------------------------------------------------------------------------------------

// Point at parameter t.
Vec2 bezier_point(const double* c, double t);

// Derivative of the given order (1, 2 or 3) at t; order 0 is the point, > 3 is zero.
Vec2 bezier_derivative(const double* c, double t, int order);

// de Casteljau split at t: left covers [0,t], right covers [t,1]; either may be null.
// left and right may not alias c.
void bezier_split(const double* c, double t, double* left, double* right);

// Arc length over [t0, t1] by adaptive Gauss–Legendre quadrature of |B'(t)|,
// to an absolute tolerance `tol` (in drawing units).
double bezier_arc_length(const double* c, double t0 = 0.0, double t1 = 1.0, double tol = 1e-9);

// Axis-aligned bounds of the curve itself (not its hull): out = {xmin, ymin, xmax, ymax}.
// Extremes are at the ends and at roots of B'(t) in (0,1).
void bezier_bounds(const double* c, double* out);

// `samples` (>= 2) points at t = k/(samples-1), written as x,y pairs to out (2*samples doubles).
void bezier_sample(const double* c, int samples, double* out);

// ---------------------------------------------------------------------------------------------
// Splines: flat control points, 3n+1 (open) or 3n (closed) points
// ---------------------------------------------------------------------------------------------

// Number of cubic segments of a spline of `point_count` control points.
int spline_segment_count(int point_count, bool closed);

// Copies segment `s` of a spline into seg (8 doubles); closed splines wrap to point 0.
void spline_segment(const double* points, int point_count, bool closed, int s, double* seg);

// Bounds of a whole spline: out = {xmin, ymin, xmax, ymax}. A spline with no segment
// (a lone point) has the bounds of its points.
void spline_bounds(const double* points, int point_count, bool closed, double* out);

}  // namespace splinekit
