#include "surface/landmarks.h"

#include "common/radix_queue.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace splinekit::surface {

void dual_distances(const TriMesh& mesh, const std::vector<Eigen::Vector3f>& centroids, int source,
                    std::vector<float>& distance) {
  const float inf = std::numeric_limits<float>::infinity();
  distance.assign(mesh.triangles.size(), inf);
  static thread_local RadixQueue queue;  // (Dijkstra: keys never fall below the last popped)
  queue.clear();
  distance[source] = 0;
  queue.push(0.f, source);
  while (!queue.empty()) {
    const auto [d, f] = queue.pop();
    if (d > distance[f]) continue;  // a stale entry
    for (int g : mesh.adjacency[f]) {
      if (g < 0) continue;
      const float dg = d + (centroids[g] - centroids[f]).norm();
      if (dg < distance[g]) {
        distance[g] = dg;
        queue.push(dg, g);
      }
    }
  }
}

namespace {

// The face farthest from the landmarks so far (an unreached one first).
int farthest(const std::vector<float>& nearest) {
  return static_cast<int>(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
}

}  // namespace

Landmarks::Landmarks(const TriMesh& mesh, const std::vector<Eigen::Vector3f>& centroids, int count) {
  const int nf = static_cast<int>(mesh.triangles.size());
  if (count <= 0 || nf == 0) return;
  count_ = std::min(count, nf);
  // The step from the first search: within face 0's component every distance is at most twice its
  // largest (the diameter bound); values beyond 16 bits (other, larger components) count as unreached.
  std::vector<float> distance, nearest(nf, std::numeric_limits<float>::infinity());
  dual_distances(mesh, centroids, 0, distance);
  float eccentricity = 0;
  for (float d : distance)
    if (std::isfinite(d)) eccentricity = std::max(eccentricity, d);
  step_ = std::max(2.0 * eccentricity, 1e-30) / (kUnreached - 1);
  int next = farthest(distance);
  values_.assign(static_cast<size_t>(nf) * count_, kUnreached);
  for (int l = 0; l < count_; ++l) {
    faces_.push_back(next);
    dual_distances(mesh, centroids, next, distance);
    for (int f = 0; f < nf; ++f) {
      const double q = std::floor(distance[f] / step_);  // infinity stays infinite
      if (q < kUnreached) values_[static_cast<size_t>(f) * count_ + l] = static_cast<uint16_t>(q);
      nearest[f] = std::min(nearest[f], distance[f]);
    }
    next = farthest(nearest);
  }
  lo_.assign(count_, kUnreached);
  hi_.assign(count_, 0);
}

void Landmarks::set_target(const int* faces, int n) {
  for (int l = 0; l < count_; ++l) {
    uint16_t lo = kUnreached, hi = 0;
    bool reached = n > 0;
    for (int i = 0; i < n; ++i) {
      const uint16_t q = value(faces[i], l);
      reached = reached && q != kUnreached;
      lo = std::min(lo, q), hi = std::max(hi, q);
    }
    // A target face this landmark did not reach: the landmark says nothing about this target.
    lo_[l] = reached ? lo : kUnreached;
    hi_[l] = hi;
  }
}

}  // namespace splinekit::surface
