// Coarse-to-fine initial strips for long paths (phase (i) of geodesic.h, the kDual graph). On a coil, a
// fold or a limb against a body the greedy search floods and its strip keeps to the side it started
// on, and the straightening sweeps the whole band between strip and geodesic with flips; a long path
// found first on a coarser mesh of the same surface, and followed on the fine mesh, gives a strip
// that already lies near the geodesic (BENCHMARKS.md, "Surface at scale", Coarse guide).
//
// The coarse mesh is a decimation whose vertices are fine vertices (src/surface/ simplifies the file
// with meshoptimizer, which keeps a subset of the vertices and collapses edges only, so the coarse
// surface keeps the fine one's topology). A path from a to b:
//   1. a and b go to the coarse vertices nearest them on the fine mesh (a breadth-first walk over
//      fine faces to the first kept vertex);
//   2. the locally shortest path between those on the coarse mesh (its own GeodesicSolver, kDual);
//   3. on the fine mesh from a's face, face by face to the neighbour whose centroid is nearer each of
//      the coarse path's edge crossings in turn, then b (a descent in space, which at coarse-edge
//      steps does not cross between the turns of a coil) — or, on a mesh of long thin faces, where
//      the nearest centroid misleads, across the faces each segment between them crosses (a walk in
//      the faces' planes, the descent where it meets a boundary or turns back) — and the greedy
//      search on from where that stops if it is not b's face; loops removed.
// The strip is then straightened as any other (straighten.h).
#pragma once

#include "surface/dual_search.h"
#include "surface/mesh.h"
#include "surface/path.h"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace splinekit::surface {

class GeodesicSolver;

class CoarseGuide {
 public:
  // ---- Constructors ----
  // The guide of `fine` from a decimation's triangles (`count` faces, 3 fine FILE vertex indices
  // each): the coarse mesh on those vertices' positions (a mesh of its own, repaired as any file),
  // its solver built with `options` (its landmarks if it is large enough). kInvalidInput with `error`
  // naming the problem when an index is out of range, a vertex is unused in `fine`, or no face is left.
  static MeshStatus build(const TriMesh& fine, const int* triangles, int count, const ShortestPathOptions& options,
                          std::unique_ptr<CoarseGuide>& guide, std::string& error);
  ~CoarseGuide();

  // ---- Queries ----
  const TriMesh& coarse() const { return coarse_; }
  // The landmarks of the guide's own search (on its components of 1024 faces or more).
  const Landmarks& landmarks() const;
  // The work of the guide's own paths (its searches, strips and passes), summed since it was built.
  const PathStats& stats() const { return stats_; }
  // The coarse mesh's mean edge length.
  double mean_edge() const { return mean_edge_; }
  // Whether step 3 walks the coarse path's segments rather than descends towards its points: on a
  // mesh whose faces are long and thin (the median longest / shortest edge over
  // ShortestPathOptions::guide_walk_aspect), where the nearest centroid is a poor guide.
  bool walks() const { return walks_; }
  // Bytes held: the coarse mesh, its solver, the fine-to-coarse vertex table.
  size_t bytes() const;

  // ---- Strips ----
  // The fine strip from a to b along the coarse path, when that path crosses at least `min_faces`
  // coarse faces; false (strip unspecified) when it is shorter, when no kept vertex lies near a or b,
  // or a search does not reach. `search`: the fine mesh's (its centroids, the greedy search on from
  // where the descent stops, its face table for the loops).
  bool strip(const MeshPoint& a, const MeshPoint& b, int min_faces, DualSearch& search, std::vector<int>& strip,
             PathStats* stats);

 private:
  CoarseGuide(const TriMesh& fine, TriMesh coarse, std::vector<int> coarse_of_fine, const ShortestPathOptions& options);
  // The coarse mesh vertex nearest p on the fine mesh (fewest faces away, then nearest in space), -1
  // when none lies within a bounded walk.
  int nearest_kept(const MeshPoint& p);
  // Step 3, from strip.back() towards x: face by face to the neighbour whose centroid (`centroids`,
  // the fine search's) is nearer x, while one is.
  void descend_to(const Vec3& x, const std::vector<Eigen::Vector3f>& centroids, std::vector<int>& strip) const;
  // Step 3 where faces are long and thin (walks()): across the faces the segment from `at` (on
  // strip.back()) to x crosses, in each face's plane, to the face under x (`at` becomes x); false
  // where the segment meets a boundary or turns back (`at` then on the face reached).
  bool walk_to(const Vec3& x, Vec3& at, std::vector<int>& strip) const;
  // Steps 1-2: the coarse path from a to b in along_ (its points in space); false when it is shorter
  // than min_faces or none.
  bool coarse_path(const MeshPoint& a, const MeshPoint& b, int min_faces);

  const TriMesh& fine_;
  TriMesh coarse_;
  std::vector<int> coarse_of_fine_;  // #fine vertices: the coarse mesh vertex at a fine one, -1 if not kept
  std::unique_ptr<GeodesicSolver> solver_;
  GeodesicPath path_;        // scratch
  std::vector<Vec3> along_;  // the coarse path's points
  std::vector<int> queue_;   // nearest_kept's walk
  std::vector<int> tail_;    // the search after the descent
  bool walks_ = false;       // walks()
  double mean_edge_ = 0;     // mean_edge()
  PathStats stats_;          // stats()
};

}  // namespace splinekit::surface
