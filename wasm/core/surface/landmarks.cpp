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

// The face with the largest value (the first such); with `finite`, the largest finite one.
int farthest(const std::vector<float>& values, bool finite = false) {
  int best = -1;
  for (int f = 0; f < static_cast<int>(values.size()); ++f)
    if ((!finite || std::isfinite(values[f])) && (best < 0 || values[f] > values[best])) best = f;
  return std::max(best, 0);
}

// The connected components of the dual graph: each face's component, and the components' faces
// (a face of each: its first; their sizes).
struct Components {
  std::vector<int> of;                // #F
  std::vector<int> first_face, size;  // per component
};

Components components(const TriMesh& mesh) {
  const int nf = static_cast<int>(mesh.triangles.size());
  Components c;
  c.of.assign(nf, -1);
  std::vector<int> stack;
  for (int s = 0; s < nf; ++s) {
    if (c.of[s] >= 0) continue;
    const int id = static_cast<int>(c.size.size());
    c.first_face.push_back(s);
    c.size.push_back(0);
    c.of[s] = id;
    stack.assign(1, s);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      ++c.size[id];
      for (int g : mesh.adjacency[f])
        if (g >= 0 && c.of[g] < 0) c.of[g] = id, stack.push_back(g);
    }
  }
  return c;
}

}  // namespace

Landmarks::Landmarks(const TriMesh& mesh, const std::vector<Eigen::Vector3f>& centroids, int count,
                     int min_component_faces) {
  const int nf = static_cast<int>(mesh.triangles.size());
  if (count <= 0 || nf == 0) return;
  // The components that get landmarks: the largest ones (at most `count`) of at least
  // min_component_faces faces. A scan's debris (a real one: 150 specks beside a dragon of 871k
  // faces) gets none; it would otherwise take every landmark, each farthest from all the others.
  const Components parts = components(mesh);
  std::vector<int> big;
  for (int id = 0; id < static_cast<int>(parts.size.size()); ++id)
    if (parts.size[id] >= std::max(1, min_component_faces)) big.push_back(id);
  std::stable_sort(big.begin(), big.end(), [&](int x, int y) { return parts.size[x] > parts.size[y]; });
  if (big.size() > static_cast<size_t>(count)) big.resize(count);
  if (big.empty()) return;
  count_ = std::min(count, nf);
  // Each one's first landmark is the face farthest from its first face. Within a component every
  // distance is at most twice that face's largest (the diameter bound): the step fits them all in
  // 16 bits. `nearest`: per face of those components, the distance to the nearest landmark so far
  // (infinity before its component has one); -1 elsewhere (never chosen).
  std::vector<float> distance, nearest(nf, -1.f);
  std::vector<int> firsts;
  std::vector<char> chosen(parts.size.size(), 0);
  float eccentricity = 0;
  for (int id : big) {
    dual_distances(mesh, centroids, parts.first_face[id], distance);
    firsts.push_back(farthest(distance, true));  // (the seed's own distance, 0, is finite)
    eccentricity = std::max(eccentricity, distance[firsts.back()]);
    chosen[id] = 1;
  }
  for (int f = 0; f < nf; ++f)
    if (chosen[parts.of[f]]) nearest[f] = std::numeric_limits<float>::infinity();
  step_ = std::max(2.0 * eccentricity, 1e-30) / (kUnreached - 1);
  values_.assign(static_cast<size_t>(nf) * count_, kUnreached);
  for (int l = 0; l < count_; ++l) {
    const int next = l < static_cast<int>(firsts.size()) ? firsts[l] : farthest(nearest);
    faces_.push_back(next);
    dual_distances(mesh, centroids, next, distance);
    for (int f = 0; f < nf; ++f) {
      const double q = std::floor(distance[f] / step_);  // infinity stays infinite
      if (q < kUnreached) values_[static_cast<size_t>(f) * count_ + l] = static_cast<uint16_t>(q);
      if (nearest[f] >= 0) nearest[f] = std::min(nearest[f], distance[f]);
    }
  }
  lo_.assign(count_, kUnreached);
  hi_.assign(count_, 0);
}

int Landmarks::best_between(int f, int g) const {
  int best = -1, most = 0;
  for (int l = 0; l < count_; ++l) {
    const int a = value(f, l), b = value(g, l);
    if (a != kUnreached && b != kUnreached && std::abs(a - b) > most) most = std::abs(a - b), best = l;
  }
  return best;
}

void Landmarks::descend(const TriMesh& mesh, const std::vector<Eigen::Vector3f>& centroids, int l, int f, int stop,
                        std::vector<int>& faces) const {
  faces.assign(1, f);
  // Each step to the neighbour whose value falls most per length of the link: the tree's parent,
  // whose distance falls by the whole link (any other's by less), as far as the rounding tells.
  // (Values fall strictly at every step: it ends, after at most as many steps as the value.)
  for (int here = value(f, l); here > stop;) {
    int next = -1;
    double steepest = 0;
    for (int g : mesh.adjacency[f]) {
      if (g < 0 || value(g, l) >= here) continue;
      const double slope = (here - value(g, l)) / std::max(1e-30, double((centroids[g] - centroids[f]).norm()));
      if (slope > steepest) steepest = slope, next = g;
    }
    if (next < 0) return;
    faces.push_back(f = next);
    here = value(f, l);
  }
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
