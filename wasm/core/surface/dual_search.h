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
  // The edges with more than `steiner` nodes, ascending, and the prefix sums of their extra nodes
  // (#long + 1; both empty when there are none). Few on most meshes, so kept sparse: until
  // 2026-12-02 a node offset per edge (6 bytes per triangle) was stored as soon as one edge was long.
  std::vector<int> long_edges, long_extra;
  // Where to look in them: for each run of 2^kBlockBits edges (edge_block) and of 2^kBlockBits edge
  // nodes (node_block), how many long edges come before its first edge (start before its first
  // node), and one entry more at the end, so that a look-up searches only its run's long edges,
  // not all of them (a binary search over all of them on every node cost a quarter of the refined
  // search on a mesh with a few hundred long edges). Empty when there are no long edges.
  static constexpr int kBlockBits = 8;
  std::vector<int> edge_block, node_block;
  // Fills edge_block and node_block from long_edges and long_extra.
  void index_long_edges();
  // Number of nodes: F face nodes, then the edge nodes edge by edge.
  int nodes() const { return faces + edges * steiner + (long_extra.empty() ? 0 : long_extra.back()); }
  // The nodes of edge e are [first_node(e), end_node(e)).
  int first_node(int e) const {
    return long_edges.empty() ? faces + e * steiner : faces + e * steiner + long_extra[long_before(e)];
  }
  int end_node(int e) const {
    if (long_edges.empty()) return faces + (e + 1) * steiner;
    const int i = long_before(e);
    const bool is_long = i < static_cast<int>(long_edges.size()) && long_edges[i] == e;
    return faces + (e + 1) * steiner + long_extra[i + (is_long ? 1 : 0)];
  }
  // The edge an edge node lies on (node >= faces).
  int edge_of_node(int node) const;

 private:
  // How many long edges come before edge e (the index of the first long edge >= e).
  int long_before(int e) const {
    const int b = e >> kBlockBits;
    return static_cast<int>(
        std::lower_bound(long_edges.begin() + edge_block[b], long_edges.begin() + edge_block[b + 1], e) -
        long_edges.begin());
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
  // Bytes held: the graph, the search records, the face centroids and the landmark distances.
  size_t bytes() const;

  // ---- Mutators ----
  // The face strip from a to b (mesh space; consecutive faces adjacent, no face twice), or false
  // (strip empty) when b cannot be reached. Adds the nodes it expanded to stats->visited_nodes.
  bool initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats = nullptr,
                     SearchGraph graph = SearchGraph::kRefined);
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
  Vec3 node_position(int node, int edge) const;
  float edge_length(int e) const;
  int link_face(int a, int b) const;  // a face holding both nodes
  // The record of `node` (on edge `edge`, -1 for a face node); -1 when untouched.
  int slot(int node, int edge) const {
    return edge < 0 ? face_slot_[node] : edge_slot_[edge] < 0 ? -1 : edge_slot_[edge] + node - graph_.first_node(edge);
  }
  int slot(int node) const { return slot(node, node < graph_.faces ? -1 : graph_.edge_of_node(node)); }

  const TriMesh& mesh_;
  double dual_heuristic_weight_, landmark_weight_, refined_landmark_scale_;
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
  double last_length_ = 0;
  // Face centroids in single precision (the face nodes' positions: one read instead of four).
  std::vector<Eigen::Vector3f> centroids_;
  // Dual-graph distances from a few landmark faces (empty on small meshes).
  Landmarks landmarks_;
};

}  // namespace splinekit::surface
