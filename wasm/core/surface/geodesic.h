// Locally shortest geodesic paths between mesh points (b/Surf §5.1 "Point-to-point shortest path",
// §6.2 for the refined graph). Three phases, each in its own unit:
//   (i)   an initial strip of faces from a search on the (refined) dual graph (dual_search.h), or for
//         a long kDual path on a mesh with a coarse guide, the strip that follows the path found on
//         the guide, and for a long kRefined one, the search kept to the guide's corridor of
//         near-shortest ways (coarse_guide.h);
//   (ii)  the strip is unfolded into the plane (unfold.h) and the funnel algorithm finds the
//         shortest path inside it (funnel.h);
//   (iii) the strip is straightened by flips at the path's reflex vertices until it is locally
//         shortest (straighten.h).
// A path is its strip of faces and the intercepts (lerps) on the edges between consecutive faces
// (path.h, with the queries on paths). This header is the entry: it includes the others.
#pragma once

#include "surface/coarse_guide.h"
#include "surface/dual_search.h"
#include "surface/geodesic_options.h"
#include "surface/mesh.h"
#include "surface/path.h"
#include "surface/straighten.h"

#include <memory>
#include <string>
#include <vector>

namespace splinekit::surface {

// Locally shortest paths on one mesh: the search graph and the straightening with their scratch,
// reused between queries (after warm-up a query allocates only its result).
class GeodesicSolver {
 public:
  // ---- Constructors ----
  // For paths on `mesh`, which must outlive the solver.
  explicit GeodesicSolver(const TriMesh& mesh, const ShortestPathOptions& options = {});
  // (the straightening borrows the search's per-face table: not copyable)
  GeodesicSolver(const GeodesicSolver&) = delete;
  GeodesicSolver& operator=(const GeodesicSolver&) = delete;
  ~GeodesicSolver();

  // ---- Queries ----
  const TriMesh& mesh() const { return mesh_; }
  const DualGraph& graph() const { return search_.graph(); }
  const Landmarks& landmarks() const { return search_.landmarks(); }
  // Bytes held for the mesh: the graph, the search records, the face centroids, the vertex angle sums,
  // the coarse guide.
  size_t bytes() const { return search_.bytes() + straightener_.bytes() + (guide_ ? guide_->bytes() : 0); }
  // The coarse guide (null without one).
  const CoarseGuide* coarse_guide() const { return guide_.get(); }

  // ---- Set-up ----
  // Long kDual paths follow their way on a decimation of the mesh (coarse_guide.h): `count` faces of
  // 3 FILE vertex indices each, all vertices of the mesh (e.g. meshoptimizer's simplification).
  // kInvalidInput with `error` naming the problem, the solver's guide unchanged.
  MeshStatus set_coarse_guide(const int* triangles, int count, std::string& error);

  // ---- Paths ----
  // The locally shortest path from a to b (mesh space). Always succeeds on a connected mesh; when b
  // cannot be reached (another component) the path is empty (strip empty) and false is returned.
  // With the kDual graph, a long strip is also found down a landmark's distance field
  // (landmark_descent) and, unless that one's funnel path is shorter, searched from b to a
  // (dual_reverse_search_faces); the candidate whose funnel path is shortest is straightened.
  bool shortest_path(const MeshPoint& a, const MeshPoint& b, GeodesicPath& path, PathStats* stats = nullptr,
                     SearchGraph graph = SearchGraph::kRefined);

  // Phase (i) alone (for tests and benchmarks): the face strip from a to b.
  bool initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats = nullptr,
                     SearchGraph graph = SearchGraph::kRefined) {
    const bool reached = search_.initial_strip(a, b, strip, stats, graph);
    search_length_ = search_.last_length();
    return reached;
  }
  // The search-graph length of the last initial_strip's (or searched shortest_path's) path (of a
  // kDual path with candidates, the strip's that was straightened; NaN for the landmark descent's).
  double last_search_length() const { return search_length_; }
  // Phases (ii)+(iii) on a given strip (consecutive faces adjacent; a on strip.front(), b on
  // strip.back()); `strip` becomes the straightened path's.
  void straighten(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, GeodesicPath& path,
                  PathStats* stats = nullptr) {
    straightener_.straighten(a, b, strip, path, stats);
  }
  // Phase (i) replaced by known paths: `pieces` run from pieces.front().start to pieces.back().end,
  // each starting where the previous one ends; the strip goes through their faces (around the shared
  // point when two pieces meet at a vertex) and is straightened, in at most `max_passes` passes
  // (ShortestPathOptions::max_passes when negative). False, with `path` untouched, when two
  // consecutive pieces do not meet; false also when the passes ran out (`path` then not yet locally
  // shortest).
  bool straighten_through(const std::vector<GeodesicPath>& pieces, GeodesicPath& path, PathStats* stats = nullptr,
                          int max_passes = -1);

 private:
  // The landmark descent's candidate strip from a to b (ShortestPathOptions::landmark_descent), given
  // the funnel length of the best candidate so far: false when no landmark tells the ends apart, the
  // descent ends too far from the other end (landmark_descent_gap) or the search on finds no way.
  bool descent_strip(const MeshPoint& a, const MeshPoint& b, double shortest, std::vector<int>& strip,
                     PathStats* stats);
  // The coarse guide's strip from a to b in strip_ (its ends at least coarse_guide_faces of the guide's
  // mean edges apart by the bounds, its coarse path at least that many faces); false without a guide
  // or when not so.
  bool guided_strip(const MeshPoint& a, const MeshPoint& b, PathStats* stats);
  // Whether a and b lie at least coarse_guide_faces of the guide's mean edges apart (in space or by
  // the landmarks' bound); false without a guide.
  bool far_apart(const MeshPoint& a, const MeshPoint& b) const;
  // The length of the funnel path from a to b inside `strip` (phase (ii) alone).
  double funnel_length(const MeshPoint& a, const MeshPoint& b, const std::vector<int>& strip);

  const TriMesh& mesh_;
  DualSearch search_;
  std::unique_ptr<CoarseGuide> guide_;
  Straightener straightener_;
  std::vector<int> strip_;     // the strip between the phases
  std::vector<int> back_;      // a long kDual strip's other candidate (searched from b to a, or the descent's)
  std::vector<int> tail_;      // the descent candidate's search after the descent
  std::vector<int> fan_;       // straighten_through's: the faces around a vertex where two pieces meet
  std::vector<int> corridor_;  // the faces a guided refined search keeps to
  double search_length_ = 0;   // last_search_length()
};

}  // namespace splinekit::surface
