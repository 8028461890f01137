// Locally shortest geodesic paths between mesh points (b/Surf §5.1 "Point-to-point shortest path",
// §6.2 for the refined graph). Three phases:
//   (i)   an initial strip of faces from a search on the dual graph with the small-label-first and
//         large-label-last deque heuristics (Bertsekas) and an A* Euclidean term; faces with edges
//         longer than 5% of the bounding-box diagonal get extra graph nodes on those edges;
//   (ii)  the strip is unfolded into the plane and the funnel algorithm (Lee & Preparata) finds the
//         shortest path inside it;
//   (iii) the strip is straightened (after Xin & Wang): the reflex vertex with the largest turn has its
//         semi-star in the strip replaced by its other semi-star; if the path does not get shorter the
//         vertex is frozen; repeat until no reflex vertex is left unfrozen. Each pass flips every
//         reflex vertex whose run does not touch another's, and a flip takes in the neighbouring
//         boundary vertices that would still block the path (a "zipper", flipped at once), or rather
//         replaces the strip between the neighbouring apices by the faces along the straight line
//         between them (a "chord", which crosses many rows of vertices at once).
// A path is its strip of faces and the intercepts (lerps) on the edges between consecutive faces.
#pragma once

#include "surface/mesh.h"

#include <vector>

namespace splinekit::surface {

struct GeodesicPath {
  MeshPoint start, end;        // start on strip.front(), end on strip.back()
  std::vector<int> strip;      // faces crossed, consecutive ones adjacent
  std::vector<double> lerps;   // #strip-1: crossing of edge (t[k], t[k+1]) of strip[i] toward strip[i+1]
  // Arc length at the start, each crossing and the end (#strip+1), as the straightening measured it
  // in the unfolded strip; empty when not known (then measured when needed).
  std::vector<double> arc;
};

// The search graph of phase (i): the dual graph refined as in §6.2. Every face has a node at its
// centroid and every edge carries `steiner` nodes evenly spaced along it (more on edges longer than
// 5% of the bounding-box diagonal, one per such length), so a triangle is represented by several
// nodes and paths are not forced through centroids. Two nodes are linked when they lie on the same
// face (not on the same edge); the link remembers that face, which gives the strip. The links are
// implicit (found from the face adjacency); only the edge numbering is stored.
struct DualGraph {
  int faces = 0;
  int edges = 0;
  int steiner = 4;                      // nodes per ordinary edge
  double long_edge = 0;                 // edges longer than this get one node per such length
  std::vector<int> halfedge_edge;       // #3F: undirected edge of half-edge (f, k)
  std::vector<int> edge_halfedge;       // #E: one half-edge (3f + k) of each edge
  std::vector<int> edge_offsets;        // #E+1: first node of each edge after the F face nodes
                                        // (empty when every edge has `steiner` nodes)
  int nodes() const { return faces + (edge_offsets.empty() ? edges * steiner : edge_offsets.back()); }
  int first_node(int e) const { return faces + (edge_offsets.empty() ? e * steiner : edge_offsets[e]); }
  int end_node(int e) const { return faces + (edge_offsets.empty() ? (e + 1) * steiner : edge_offsets[e + 1]); }
  int edge_of_node(int node) const;     // node >= faces
};

// Which graph phase (i) searches. kRefined (face and edge nodes, the queue drained under the A*
// bound) finds the strip of the globally shortest path far more often; kDual (face nodes only,
// stopping at the first arrival, as in the paper) is several times cheaper and is what curve
// tracing uses, where most paths are short and start from nearby points.
enum class SearchGraph { kRefined, kDual };

struct ShortestPathOptions {
  bool straighten = true;          // phase (iii)
  bool chords = true;              // phase (iii) flips along the line between apices (else semi-stars and zippers only)
  // Phase (iii) traces a chord only where the path turns by more than this (radians); smaller
  // bends get the semi-star (and zipper) flip. Late in the straightening the path bends a little
  // at apices far apart, and a chord there walks all the way between the neighbouring apices for
  // a small gain. Measured on random whole-surface curves (OLR, 5 levels, wasm, each curve traced
  // by both builds in turn): 0.01 takes 4-7% off the trace time on spot_loop2_369k and 1% on
  // nefertiti, with curves as long within 0.1%; 0.03 saves 1.5% more on spot_loop2_369k but
  // settles more first-level sides on other (longer) local geodesics.
  double chord_min_turn = 0.01;
  int max_flips = 100000;          // safety bound on phase (iii)
  // Graph resolution (phase (i)): `steiner` nodes on every edge, and edges longer than
  // long_edge_fraction of the bounding-box diagonal get one node per such length. The paper uses
  // 5% and face nodes only; measured on the shared meshes (BENCHMARKS.md), 4 nodes per edge and 1%
  // take the share of paths within 0.5% of the exact geodesic distance from 15-96% to 99-100% (3
  // nodes: 94% on mountain and stanford_bunny; 5: 100% there, at 1.5x the time of 4).
  double long_edge_fraction = 0.01;
  int steiner = 4;
  // Weight of the A* Euclidean term in the kDual search (weighted A*). On random whole-surface
  // curves of nefertiti and spot_loop2_369k, 2 visits 7-20 times fewer nodes than 1 (the search drops
  // from most of the trace time to a tenth of it); the paths are locally shortest either way and a
  // little more often not globally (BENCHMARKS.md, dual column), which curve tracing accepts: after
  // the first level its paths join nearby points. 3 cuts the long tail of searches that must go
  // round a concave region (on spot_loop2_369k, random face pairs: p90 23k nodes visited at 2, 2.7k
  // at 3, 1.2k at 4); phase (iii)'s chords make up for the rougher strips (curves on average 0.3%
  // longer on nefertiti, 0.2% shorter on spot_loop2_369k; 4 makes nefertiti's 1% longer).
  double dual_heuristic_weight = 3;
};

// Counters for tests and benchmarks.
struct PathStats {
  int visited_nodes = 0;
  int flips = 0;
  int frozen = 0;
};

class GeodesicSolver {
 public:
  explicit GeodesicSolver(const TriMesh& mesh, const ShortestPathOptions& options = {});

  const TriMesh& mesh() const { return mesh_; }
  const DualGraph& graph() const { return graph_; }
  size_t bytes() const;

  // The locally shortest path from a to b (mesh space). Always succeeds on a connected mesh; when b
  // cannot be reached (another component) the path is empty (strip empty) and false is returned.
  bool shortest_path(const MeshPoint& a, const MeshPoint& b, GeodesicPath& path, PathStats* stats = nullptr,
                     SearchGraph graph = SearchGraph::kRefined);

  // Phase (i) alone (for tests and benchmarks): the face strip from a to b.
  bool initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats = nullptr,
                     SearchGraph graph = SearchGraph::kRefined);
  // Phases (ii)+(iii) on a given strip (consecutive faces adjacent; a on strip.front(), b on strip.back()).
  void straighten(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, GeodesicPath& path,
                  PathStats* stats = nullptr);
  // Phase (i) replaced by known paths: `pieces` run from pieces.front().start to pieces.back().end,
  // each starting where the previous one ends; the strip goes through their faces (around the shared
  // point when two pieces meet at a vertex) and is straightened. False, with `path` untouched, when
  // two consecutive pieces do not meet.
  bool straighten_through(const std::vector<GeodesicPath>& pieces, GeodesicPath& path, PathStats* stats = nullptr);

 private:
  Vec3 node_position(int node) const;
  int link_face(int a, int b) const;  // a face holding both nodes

  const TriMesh& mesh_;
  ShortestPathOptions options_;
  DualGraph graph_;
  // Search scratch, reused between queries. Only the nodes a search touches get a record, so the
  // per-node cost is one int (slot_: the node's record, -1 when untouched; also the loop-removal
  // table of strips, -1 everywhere between uses).
  struct Visit {
    float dist, heuristic;        // from the source; A* term to the target
    int node, parent;             // parent: a node, -1 at the source
    Eigen::Vector3f position;
    bool queued;
  };
  std::vector<int> slot_;
  std::vector<Visit> visits_;
  // Face centroids in single precision (the face nodes' positions: one read instead of four).
  std::vector<Eigen::Vector3f> centroids_;
  // Angle sum around each vertex, filled in when phase (iii) first needs it (NaN until then).
  std::vector<double> angle_sums_;
};

// ---- Paths --------------------------------------------------------------------------------------

// Start, every edge crossing, end (mesh points; crossings on strip[i]'s shared edge, expressed on strip[i]).
void path_points(const TriMesh& mesh, const GeodesicPath& path, std::vector<MeshPoint>& points);
void path_positions(const TriMesh& mesh, const GeodesicPath& path, std::vector<Vec3>& positions);
double path_length(const TriMesh& mesh, const GeodesicPath& path);
// The point at arc-length fraction t in [0, 1].
MeshPoint eval_path(const TriMesh& mesh, const GeodesicPath& path, double t);
// The part of the path between fractions t0 <= t1 (a path again: strip and lerps).
GeodesicPath sub_path(const TriMesh& mesh, const GeodesicPath& path, double t0, double t1);
GeodesicPath reversed(const TriMesh& mesh, const GeodesicPath& path);

// A tangent vector at a point: a 3D vector in the plane of `face`, which contains the point.
struct Tangent {
  int face = -1;
  Vec3 dir = Vec3::Zero();
};
// Unit direction in which the path leaves its start / arrives at its end (zero dir for a point path).
Tangent start_tangent(const TriMesh& mesh, const GeodesicPath& path);
Tangent end_tangent(const TriMesh& mesh, const GeodesicPath& path);

}  // namespace splinekit::surface
