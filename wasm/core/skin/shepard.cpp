#include "shepard.h"

#include <cmath>
#include <vector>

namespace splinekit::skin {

namespace {

// The squared diagonal of the handles' bounding box (1 when they coincide): the scale at which a
// point counts as lying on a handle. dim: 2 or 3 coordinates per point.
double spread2(const double* handles, int h, int dim) {
  double s2 = 0;
  for (int a = 0; a < dim; ++a) {
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < h; ++i) lo = std::fmin(lo, handles[dim * i + a]), hi = std::fmax(hi, handles[dim * i + a]);
    s2 += (hi - lo) * (hi - lo);
  }
  return s2 > 0 ? s2 : 1.0;
}

// Squared distances from p (dim coordinates) to every handle into d2; returns the index of a
// handle the point coincides with (relative to the handle spread), or -1, and the smallest
// distance in dmin2.
int distances(const double* handles, int h, const double* p, int dim, double scale2, double* d2, double& dmin2) {
  int at = -1;
  dmin2 = INFINITY;
  for (int i = 0; i < h; ++i) {
    d2[i] = 0;
    for (int a = 0; a < dim; ++a) d2[i] += (p[a] - handles[dim * i + a]) * (p[a] - handles[dim * i + a]);
    dmin2 = std::fmin(dmin2, d2[i]);
    if (at < 0 && d2[i] <= 1e-24 * scale2) at = i;
  }
  return at;
}

}  // namespace

void shepard_weights(const double* handles, int h, const double* points, int n, double power, double* out) {
  shepard_weights_nd(handles, h, points, n, 2, power, out);
}

void shepard_weights_nd(const double* handles, int h, const double* points, int n, int dim, double power, double* out) {
  std::vector<double> d2(h);
  const double scale2 = spread2(handles, h, dim);
  for (int p = 0; p < n; ++p) {
    double dmin2;
    const int at = distances(handles, h, points + size_t(dim) * p, dim, scale2, d2.data(), dmin2);
    double* w = out + size_t(p) * h;
    if (at >= 0) {
      for (int i = 0; i < h; ++i) w[i] = i == at ? 1.0 : 0.0;
      continue;
    }
    // phi_i = d_i^-k, computed relative to the nearest handle to stay finite for large k.
    double sum = 0;
    if (power == 2.0)
      for (int i = 0; i < h; ++i) sum += w[i] = dmin2 / d2[i];  // the default: no pow() per weight
    else
      for (int i = 0; i < h; ++i) sum += w[i] = std::pow(dmin2 / d2[i], 0.5 * power);
    for (int i = 0; i < h; ++i) w[i] /= sum;
  }
}

void shepard_gradients(const double* handles, int h, const double* points, int n, double power, double* out) {
  std::vector<double> d2(h), phi(h), gx(h), gy(h);
  const double scale2 = spread2(handles, h, 2);
  for (int p = 0; p < n; ++p) {
    const double x = points[2 * p], y = points[2 * p + 1];
    double dmin2;
    const int at = distances(handles, h, points + 2 * size_t(p), 2, scale2, d2.data(), dmin2);
    double* g = out + size_t(p) * h * 2;
    if (at >= 0) {
      for (int i = 0; i < 2 * h; ++i) g[i] = 0.0;
      continue;
    }
    // With phi_i = d_i^-k: grad phi_i = -k d_i^-k-2 (p - h_i); w_i = phi_i / S,
    // grad w_i = (grad phi_i - w_i sum_j grad phi_j) / S. A common scale of phi cancels.
    double sum = 0, sx = 0, sy = 0;
    for (int i = 0; i < h; ++i) {
      phi[i] = std::pow(dmin2 / d2[i], 0.5 * power);
      gx[i] = -power * phi[i] / d2[i] * (x - handles[2 * i]);
      gy[i] = -power * phi[i] / d2[i] * (y - handles[2 * i + 1]);
      sum += phi[i];
      sx += gx[i];
      sy += gy[i];
    }
    for (int i = 0; i < h; ++i) {
      const double w = phi[i] / sum;
      g[2 * i] = (gx[i] - w * sx) / sum;
      g[2 * i + 1] = (gy[i] - w * sy) / sum;
    }
  }
}

}  // namespace splinekit::skin
