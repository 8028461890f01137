// Phase (i) of a locally shortest path (b/Surf §5.1 "Point-to-point shortest path", §6.2 for the
// refined graph): an initial strip of faces from a search on the dual graph, with the
// small-label-first and large-label-last deque heuristics (Bertsekas, "A simple and fast label
// correcting algorithm for shortest paths", 1993) and an A* Euclidean term.
#pragma once

#include "surface/geodesic_options.h"
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
// adjacency); only the edge numbering is stored.
struct DualGraph {
  int faces = 0;
  int edges = 0;
  int steiner = 4;                 // nodes per ordinary edge
  double long_edge = 0;            // edges longer than this get one node per such length
  std::vector<int> halfedge_edge;  // #3F: undirected edge of half-edge (f, k)
  std::vector<int> edge_halfedge;  // #E: one half-edge (3f + k) of each edge
  std::vector<int> edge_offsets;   // #E+1: first node of each edge after the F face nodes
                                   // (empty when every edge has `steiner` nodes)
  // Number of nodes: F face nodes, then the edge nodes edge by edge.
  int nodes() const { return faces + (edge_offsets.empty() ? edges * steiner : edge_offsets.back()); }
  // The nodes of edge e are [first_node(e), end_node(e)).
  int first_node(int e) const { return faces + (edge_offsets.empty() ? e * steiner : edge_offsets[e]); }
  int end_node(int e) const { return faces + (edge_offsets.empty() ? (e + 1) * steiner : edge_offsets[e + 1]); }
  // The edge an edge node lies on (node >= faces).
  int edge_of_node(int node) const;
};

// A growable ring buffer of ints: the deque of the SLF/LLL search.
class RingDeque {
 public:
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  int front() const { return data_[head_]; }
  void clear() { head_ = size_ = 0; }
  void push_back(int x) {
    grow();
    data_[(head_ + size_) & mask_] = x;
    ++size_;
  }
  void push_front(int x) {
    grow();
    head_ = (head_ + mask_) & mask_;
    data_[head_] = x;
    ++size_;
  }
  int pop_front() {
    const int x = data_[head_];
    head_ = (head_ + 1) & mask_;
    --size_;
    return x;
  }

 private:
  void grow() {
    if (size_ < data_.size()) return;
    std::vector<int> next(std::max<size_t>(64, 2 * data_.size()));
    for (size_t i = 0; i < size_; ++i) next[i] = data_[(head_ + i) & mask_];
    data_.swap(next);
    head_ = 0;
    mask_ = data_.size() - 1;
  }
  std::vector<int> data_;
  size_t head_ = 0, size_ = 0, mask_ = 0;
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
  // Bytes held: the graph, the search records and the face centroids.
  size_t bytes() const;

  // ---- Mutators ----
  // The face strip from a to b (mesh space; consecutive faces adjacent, no face twice), or false
  // (strip empty) when b cannot be reached. Adds the nodes it expanded to stats->visited_nodes.
  bool initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats = nullptr,
                     SearchGraph graph = SearchGraph::kRefined);
  // A table of #nodes (>= #F) entries, -1 everywhere between calls: the search's, lent to
  // remove_loops and the straightening between searches (per-face marks) so the mesh pays for one.
  std::vector<int>& face_marks() { return slot_; }

 private:
  Vec3 node_position(int node) const;
  int link_face(int a, int b) const;  // a face holding both nodes

  const TriMesh& mesh_;
  double dual_heuristic_weight_;
  DualGraph graph_;
  // Search scratch, reused between queries. Only the nodes a search touches get a record, so the
  // per-node cost is one int (slot_: the node's record, -1 when untouched; also the loop-removal
  // table of strips, -1 everywhere between uses).
  struct Visit {
    float dist, heuristic;  // from the source; A* term to the target
    int node, parent;       // parent: a node, -1 at the source
    Eigen::Vector3f position;
    bool queued;
  };
  std::vector<int> slot_;
  std::vector<Visit> visits_;
  RingDeque queue_;
  std::vector<int> sources_, targets_;  // faces holding a and b
  // Face centroids in single precision (the face nodes' positions: one read instead of four).
  std::vector<Eigen::Vector3f> centroids_;
};

}  // namespace splinekit::surface
