// Phase (i) of a locally shortest path (b/Surf §5.1 "Point-to-point shortest path", §6.2 for the
// refined graph): an initial strip of faces from an A* search on the dual graph (a radix heap on
// distance + A* term, common/radix_queue.h; the search ends when the smallest key reaches the best
// arrival). The A* term
// is the larger of the Euclidean distance to the target and the landmark bound (landmarks.h), which
// knows the surface: on coils and folds, where the Euclidean term says little, the search then
// expands the nodes near the path rather than the mesh. (Until 2026-12-02 the search was label
// correcting, with the SLF/LLL deque of Bertsekas 1993: it re-expanded nodes, and a tighter bound
// did not make it cheaper.)
#pragma once

#include "common/radix_queue.h"
#include "surface/geodesic_options.h"
#include "surface/landmarks.h"
#include "surface/mesh.h"

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace splinekit::surface {

// The search graph: the dual graph refined as in §6.2. Every face has a node at its centroid and
// every edge carries `steiner` nodes evenly spaced along it (more on edges longer than `long_edge`,
// one per such length), so a triangle is represented by several nodes and paths are not forced
// through centroids. Two nodes are linked when they lie on the same face (not on the same edge);
// the link remembers that face, which gives the strip. The links are implicit (found from the face
// adjacency); only the edge numbering is stored. The refined search measures its paths along
// straight runs across the faces (windows, dual_search.cpp) rather than link by link, so that two
// nodes per edge find the strip of the shortest path as often as four did on the graph's links.
struct DualGraph {
  int faces = 0;
  int edges = 0;
  int steiner = 2;                 // nodes per ordinary edge
  double long_edge = 0;            // edges longer than this get one node per such length
  std::vector<int> halfedge_edge;  // #3F: undirected edge of half-edge (f, k)
  std::vector<int> edge_halfedge;  // #E: one half-edge (3f + k) of each edge
  // The edges with more than `steiner` nodes (long edges), ascending; where each one's nodes start
  // after the ordinary ones (the prefix sums of their node counts, #long + 1); and one bit per edge,
  // set for the long ones. All empty when there are none. Few edges are long on most meshes, so an
  // ordinary edge's nodes are found by a multiplication and one bit (until 2026-12-02 a node offset
  // per edge, 6 bytes per triangle, was stored as soon as one edge was long; until 2026-12-03 the
  // long edges' nodes lay among the others, and every look-up searched the long edges before it,
  // which cost the refined search 8-25% on the folded body with a few hundred long edges).
  std::vector<int> long_edges, long_first;
  std::vector<uint64_t> long_bits;
  // Number of nodes: F face nodes, `steiner` for every edge (a long edge's stay unused), then the
  // long edges' own, edge by edge.
  int nodes() const { return faces + edges * steiner + (long_first.empty() ? 0 : long_first.back()); }
  bool is_long(int e) const { return !long_bits.empty() && (long_bits[e >> 6] >> (e & 63) & 1); }
  // The nodes of edge e are [first, end) (one look-up among the long edges for both ends).
  struct NodeRange {
    int first, end;
  };
  NodeRange node_range(int e) const {
    if (!is_long(e)) return {faces + e * steiner, faces + (e + 1) * steiner};
    const int i = long_index(e), tail = faces + edges * steiner;
    return {tail + long_first[i], tail + long_first[i + 1]};
  }
  // The edge an edge node lies on (node >= faces).
  int edge_of_node(int node) const {
    const int local = node - faces;
    if (local < edges * steiner) return local / steiner;
    const int tail = local - edges * steiner;  // the long edge whose nodes start last at or before it
    return long_edges[std::upper_bound(long_first.begin(), long_first.end(), tail) - long_first.begin() - 1];
  }

 private:
  // The index of long edge e among long_edges.
  int long_index(int e) const {
    return static_cast<int>(std::lower_bound(long_edges.begin(), long_edges.end(), e) - long_edges.begin());
  }
};

// The graph of a mesh and the search over it, with its scratch reused between queries.
class DualSearch {
 public:
  // ---- Constructors ----
  // Builds the graph of `mesh` (which must outlive the search) with options.steiner nodes per edge
  // and options.long_edge_fraction; the kDual search weighs its A* term by
  // options.dual_heuristic_weight.
  DualSearch(const TriMesh& mesh, const ShortestPathOptions& options);

  // ---- Queries ----
  const DualGraph& graph() const { return graph_; }
  const Landmarks& landmarks() const { return landmarks_; }
  // The faces' centroids (single precision, relative to a point of the mesh's box: differences only).
  const std::vector<Eigen::Vector3f>& centroids() const { return centroids_; }
  // How much longer the dual graph's paths are than straight lines, measured when the graph is
  // built: from 32 faces spread over the mesh, a Dijkstra search over the centroids out to 20 times
  // the face's size (the square root of its area); of the faces it reaches 10 to 20 sizes away in
  // space, the 90th percentile of (graph distance / distance in space); 1 when none is reached or
  // neither options.dual_stretch_weight nor (with landmarks) options.refined_landmark_share asks
  // for it (then it is not measured).
  // Near-regular faces measure about 1.3-1.8, long thin ones far more (a 7:1 quad split in two, 4.5
  // along its short side).
  double dual_stretch() const { return dual_stretch_; }
  // The weight of the kDual search's Euclidean term: options.dual_heuristic_weight, or
  // options.dual_stretch_weight times dual_stretch() if that is larger.
  double dual_weight() const { return dual_weight_; }
  // Bytes held: the graph, the search records, the face centroids and the landmark distances.
  size_t bytes() const;

  // ---- Mutators ----
  // The face strip from a to b (mesh space; consecutive faces adjacent, no face twice), or false
  // (strip empty) when b cannot be reached. Adds the nodes it expanded to stats->visited_nodes.
  // With a `corridor`, the search keeps to its faces (and those of a and b).
  bool initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats = nullptr,
                     SearchGraph graph = SearchGraph::kRefined, const std::vector<int>* corridor = nullptr);
  // The search-graph length of the last initial_strip's path, from a to b (the A* distance, weighted
  // as its Euclidean term in the kDual search; infinity when b was not reached, 0 when a and b share
  // a face).
  double last_length() const { return last_length_; }
  // A table of #nodes (>= #F) entries, -1 everywhere between calls: the search's, lent to
  // remove_loops and the straightening between searches (per-face marks) so the mesh pays for one.
  std::vector<int>& face_marks() { return face_slot_; }

  // A search record: what the search knows of one node it touched (public for the refined search's
  // window helper in dual_search.cpp).
  struct Visit {
    float dist, heuristic;  // from the source; A* term to the target
    int node, parent;       // parent: a node, -1 at the source
    Eigen::Vector3f position;
    bool closed;  // expanded (never again: with the scaled landmark term the A* term is not
                  // quite consistent, and re-expanding nodes costs more than it gains)
    // The refined search's window (see Window in dual_search.cpp): the face the node was reached
    // through, the pseudo-source (laid in that face's plane) and its distance, and the stretch
    // [lo, hi] of the node's edge (along it from its first end) that the source sees straight.
    int via;
    Eigen::Vector3f source;
    float source_dist, lo, hi;
  };

 private:
  Vec3 node_position(int node, int edge) const;  // (relative to origin_)
  float edge_length(int e) const;
  int link_face(int a, int b) const;  // a face holding both nodes
  // The record of `node` (on edge `edge`, -1 for a face node); -1 when untouched.
  int slot(int node, int edge) const {
    return edge < 0               ? face_slot_[node]
           : edge_slot_[edge] < 0 ? -1
                                  : edge_slot_[edge] + node - graph_.node_range(edge).first;
  }
  int slot(int node) const { return slot(node, node < graph_.faces ? -1 : graph_.edge_of_node(node)); }

  const TriMesh& mesh_;
  // dual_stretch() (the face marks are its scratch).
  double measure_stretch();

  double dual_weight_, landmark_weight_, refined_landmark_scale_;
  double dual_stretch_ = 1;
  DualGraph graph_;
  // Search scratch, reused between queries. Only the nodes a search touches get a record; the nodes
  // of an edge get theirs together, so the per-node cost is one int per face and one per edge
  // (face_slot_, edge_slot_: the record of the face node, of the edge's first node; -1 when
  // untouched; face_slot_ is also the loop-removal table of strips, -1 everywhere between uses).

  std::vector<int> face_slot_, edge_slot_;
  std::vector<Visit> visits_;
  // The open nodes' records by key (dist + heuristic when pushed); an entry whose key no longer
  // matches its record's is stale and skipped.
  RadixQueue queue_;
  std::vector<int> sources_, targets_;  // faces holding a and b
  // One bit per face: the corridor of the search under way (all clear between searches; allocated
  // by the first search that has one).
  std::vector<uint64_t> corridor_bits_;
  double last_length_ = 0;
  // The search's positions (node records, windows, centroids) are in single precision relative to
  // `origin_`, the centre of the mesh's bounding box (TriMesh::centre): a float keeps 7 digits of a coordinate, which
  // for a scan in georeferenced coordinates (millions of units away, a few units across) are not its
  // shape's. local(): a point of mesh space in those coordinates.
  Vec3 origin_ = Vec3::Zero();
  Eigen::Vector3f local(const Vec3& p) const { return (p - origin_).cast<float>(); }
  // Face centroids in single precision, relative to origin_ (the face nodes' positions: one read
  // instead of four).
  std::vector<Eigen::Vector3f> centroids_;
  // Dual-graph distances from a few landmark faces (empty on small meshes).
  Landmarks landmarks_;
};

}  // namespace splinekit::surface
