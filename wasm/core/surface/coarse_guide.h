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
  // The fine faces near every way from a to b on the guide at most `slack` longer than its shortest:
  // the coarse vertices v with d(a', v) + d(v, b') <= (1 + slack) d(a', b') + slack_edges e (e: the
  // guide's mean edge; the guide's lengths stray from the mesh's by a share of a long way and by
  // about an edge on a short one) (a', b': the kept
  // vertices nearest a and b; d: Dijkstra over the coarse mesh with the fast-marching update across
  // its edges, through_edge; from a' out to (1 + slack) d(a', b'), from b' only through vertices
  // that can still pass the test), and the fine faces within one coarse mean edge of them. A refined search inside it
  // finds the strip of the shortest path wherever the guide's shape says the way might go: where two ways round a tube
  // or a limb are about as long, both (a corridor around the guide's one path leaves out the other, and on the knotted
  // tube of the benchmarks a tenth of the shortest paths went the other way). False when no kept vertex lies near a or
  // b, or b' cannot be reached from a'. face_marks: as remove_loops'.
  bool corridor(const MeshPoint& a, const MeshPoint& b, double slack, double slack_edges, std::vector<int>& face_marks,
                std::vector<int>& faces);

 private:
  CoarseGuide(const TriMesh& fine, TriMesh coarse, std::vector<int> coarse_of_fine, std::vector<int> fine_of_coarse,
              const ShortestPathOptions& options);
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

  // corridor()'s distance at w across the coarse edge from v to u (dv and du from the source; the
  // three corners of a face): from the point source in the face's plane that lies dv from v and du
  // from u on the far side of the edge, where the straight way from it to w crosses the edge, else
  // infinity (a fast-marching update). Along edges alone a path zigzags, its length depends on its
  // direction, and on the noisy spot and the folded body the true way lay outside a 1% corridor.
  double through_edge(int v, double dv, int u, double du, int w) const;

  const TriMesh& fine_;
  TriMesh coarse_;
  std::vector<int> coarse_of_fine_;  // #fine vertices: the coarse mesh vertex at a fine one, -1 if not kept
  std::vector<int> fine_of_coarse_;  // #coarse vertices: the fine vertex of each
  std::unique_ptr<GeodesicSolver> solver_;
  GeodesicPath path_;        // scratch
  std::vector<Vec3> along_;  // the coarse path's points
  std::vector<int> queue_;   // nearest_kept's walk
  std::vector<int> tail_;    // the search after the descent
  // corridor()'s: the distances from a' and b' (infinity where not reached; as many as coarse
  // vertices, allocated by the first corridor), their queue, the coarse vertices each reached, a fan
  // and the seed faces.
  std::vector<double> from_a_, from_b_;
  std::vector<std::pair<double, int>> heap_;
  std::vector<int> reached_, reached_b_, fan_, seeds_;
  bool walks_ = false;    // walks()
  double mean_edge_ = 0;  // mean_edge()
  PathStats stats_;       // stats()
};

}  // namespace splinekit::surface
