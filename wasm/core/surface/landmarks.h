// Landmark lower bounds for phase (i)'s search (dual_search.h): A*, landmarks and the triangle
// inequality ("ALT"), after Goldberg & Harrelson, "Computing the shortest path: A* search meets graph
// theory", SODA 2005. For a landmark L and any two nodes x, t of a graph with distance d,
//     d(x, t) >= |d(L, t) - d(L, x)|,
// so the largest such difference over a few landmarks bounds the distance still to go from below,
// knowing the surface: on a coil, a fold or a limb against a body (points close in space, far apart on
// the surface) the Euclidean term says little and the search floods, while the landmark term follows
// the surface.
//
// Here the graph is the dual graph (face centroids, linked across shared edges by straight segments),
// the one SearchGraph::kDual searches: the bound is admissible there (the kRefined search divides it
// by the graph's stretch, ShortestPathOptions::refined_landmark_share). Landmarks go to the largest
// connected components (of at least a given size; a scan's specks of debris get none, as searches
// there end at once): in each of them first the face farthest from its first face, then by
// farthest-point sampling over them all (each the face farthest from those chosen so far). Distances are quantised to
// 16 bits per face and landmark (rounded down to a multiple of `step`; 0xFFFF: not reached), the faces' values stored
// together.
#pragma once

#include "surface/mesh.h"

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace splinekit::surface {

class Landmarks {
 public:
  static constexpr uint16_t kUnreached = 0xFFFF;

  // ---- Constructors ----
  Landmarks() = default;
  // `count` landmarks on the dual graph of `mesh` whose face centroids are `centroids` (#F), in its
  // components of at least min_component_faces faces (the `count` largest); none when count <= 0 or
  // no component is that large.
  Landmarks(const TriMesh& mesh, const std::vector<Eigen::Vector3f>& centroids, int count, int min_component_faces = 1);

  // ---- Queries ----
  int count() const { return count_; }
  bool empty() const { return count_ == 0; }
  // The landmark faces, in the order chosen.
  const std::vector<int>& faces() const { return faces_; }
  // The quantisation step: a stored value q stands for a distance in [q·step, (q+1)·step).
  double step() const { return step_; }
  // The stored value of face f for landmark l.
  uint16_t value(int f, int l) const { return values_[static_cast<size_t>(f) * count_ + l]; }
  size_t bytes() const { return values_.capacity() * sizeof(uint16_t) + faces_.capacity() * sizeof(int); }

  // A lower bound on the dual-graph distance between faces f and g (0 when nothing is known).
  double bound_between(int f, int g) const {
    const int l = best_between(f, g);
    return l < 0 ? 0 : (std::abs(value(f, l) - value(g, l)) - 1) * step_;
  }
  // The landmark whose values at faces f and g differ most (the one that bounds their distance best),
  // -1 when none reached both or all agree.
  int best_between(int f, int g) const;
  // A path down landmark l's distance field from face f, along the dual graph's shortest-path tree
  // towards the landmark (faces' centroids `centroids`, as built): to a face of value `stop` or less
  // (or one with no smaller neighbour). `faces` gets f and the faces passed, consecutive ones adjacent.
  void descend(const TriMesh& mesh, const std::vector<Eigen::Vector3f>& centroids, int l, int f, int stop,
               std::vector<int>& faces) const;
  // A target: a set of faces (any of which ends a path), as the interval of its faces' values per
  // landmark. Set once per search, then bound() per node.
  void set_target(const int* faces, int n);
  // A lower bound on the dual-graph distance from face f to the nearest face of the target (0 when
  // nothing is known).
  double bound(int f) const {
    if (count_ == 0) return 0;
    const uint16_t* q = &values_[static_cast<size_t>(f) * count_];
    int best = 0;
    for (int l = 0; l < count_; ++l) {
      if (q[l] == kUnreached || lo_[l] == kUnreached) continue;
      // d(f, t) >= d(L, t) - d(L, f) > lo - (q + 1), and >= d(L, f) - d(L, t) > q - (hi + 1).
      best = std::max(best, std::max(static_cast<int>(lo_[l]) - q[l] - 1, static_cast<int>(q[l]) - hi_[l] - 1));
    }
    return best * step_;
  }

 private:
  int count_ = 0;
  double step_ = 0;
  std::vector<int> faces_;
  std::vector<uint16_t> values_;   // #F × count, face-major
  std::vector<uint16_t> lo_, hi_;  // the target's interval per landmark (set_target)
};

// Distances on the dual graph of `mesh` (centroids linked across shared edges) from `source` to every
// face (infinity where not reached): a Dijkstra search. `distance` is resized to #F.
void dual_distances(const TriMesh& mesh, const std::vector<Eigen::Vector3f>& centroids, int source,
                    std::vector<float>& distance);

}  // namespace splinekit::surface
