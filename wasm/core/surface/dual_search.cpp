#include "surface/dual_search.h"

#include "surface/path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace splinekit::surface {

namespace {

// Faces that contain a point: its face, the neighbour across the edge it lies on, or its vertex's fan.
void faces_of_point(const TriMesh& mesh, const MeshPoint& p, std::vector<int>& faces) {
  faces.clear();
  const PointLocation where = locate(mesh, p);
  if (where.kind == PointLocation::Kind::kVertex) {
    bool closed;
    vertex_fan(mesh, where.index, faces, closed);
    if (std::find(faces.begin(), faces.end(), p.face) == faces.end()) faces.push_back(p.face);
    return;
  }
  faces.push_back(p.face);
  if (where.kind == PointLocation::Kind::kEdge && mesh.adjacency[p.face][where.index] >= 0)
    faces.push_back(mesh.adjacency[p.face][where.index]);
}

}  // namespace

int DualGraph::edge_of_node(int node) const {
  const int local = node - faces;
  if (edge_offsets.empty()) return local / steiner;
  return static_cast<int>(std::upper_bound(edge_offsets.begin(), edge_offsets.end(), local) - edge_offsets.begin()) - 1;
}

DualSearch::DualSearch(const TriMesh& mesh, const ShortestPathOptions& options)
    : mesh_(mesh), dual_heuristic_weight_(options.dual_heuristic_weight) {
  const int nf = static_cast<int>(mesh.triangles.size());
  graph_.faces = nf;
  graph_.steiner = std::max(1, options.steiner);
  graph_.long_edge = options.long_edge_fraction * mesh.scale;
  graph_.halfedge_edge.assign(3 * static_cast<size_t>(nf), -1);
  std::vector<int> counts;
  bool uniform = true;
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.adjacency[f][k];
      if (g >= 0 && g < f) {  // numbered from the other side already
        graph_.halfedge_edge[3 * f + k] = graph_.halfedge_edge[3 * g + edge_to(mesh, g, f)];
        continue;
      }
      graph_.halfedge_edge[3 * f + k] = static_cast<int>(graph_.edge_halfedge.size());
      graph_.edge_halfedge.push_back(3 * f + k);
      const double len = (mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]]).norm();
      const int extra = len > graph_.long_edge ? static_cast<int>(std::ceil(len / graph_.long_edge)) - 1 : 0;
      counts.push_back(std::max(graph_.steiner, extra));
      uniform = uniform && counts.back() == graph_.steiner;
    }
  }
  graph_.edges = static_cast<int>(graph_.edge_halfedge.size());
  if (!uniform) {
    graph_.edge_offsets.assign(1, 0);
    for (int c : counts) graph_.edge_offsets.push_back(graph_.edge_offsets.back() + c);
  }
  slot_.assign(graph_.nodes(), -1);
  centroids_.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    centroids_[f] = ((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3).cast<float>();
  }
}

size_t DualSearch::bytes() const {
  return (graph_.halfedge_edge.capacity() + graph_.edge_halfedge.capacity() + graph_.edge_offsets.capacity()) *
             sizeof(int) +
         slot_.capacity() * sizeof(int) + visits_.capacity() * sizeof(Visit) +
         centroids_.capacity() * sizeof(centroids_[0]);
}

// Position of graph node `node`: a face centroid, or a point along an edge.
Vec3 DualSearch::node_position(int node) const {
  if (node < graph_.faces) return centroids_[node].cast<double>();
  const int e = graph_.edge_of_node(node);
  const int first = graph_.first_node(e), count = graph_.end_node(e) - first;
  const int h = graph_.edge_halfedge[e];
  const auto& t = mesh_.triangles[h / 3];
  const double s = double(node - first + 1) / (count + 1);
  return (1 - s) * mesh_.positions[t[h % 3]] + s * mesh_.positions[t[(h % 3 + 1) % 3]];
}

// The faces of a node: itself, or the one or two faces of its edge.
static void node_faces(const TriMesh& mesh, const DualGraph& graph, int node, int faces[2]) {
  if (node < graph.faces) {
    faces[0] = node, faces[1] = -1;
    return;
  }
  const int h = graph.edge_halfedge[graph.edge_of_node(node)];
  faces[0] = h / 3;
  faces[1] = mesh.adjacency[h / 3][h % 3];
}

int DualSearch::link_face(int a, int b) const {
  int fa[2], fb[2];
  node_faces(mesh_, graph_, a, fa);
  node_faces(mesh_, graph_, b, fb);
  for (int x : fa)
    for (int y : fb)
      if (x >= 0 && x == y) return x;
  return -1;
}

bool DualSearch::initial_strip(const MeshPoint& a, const MeshPoint& b, std::vector<int>& strip, PathStats* stats,
                               SearchGraph graph) {
  const bool dual = graph == SearchGraph::kDual;
  strip.clear();
  const int nf = graph_.faces;
  std::vector<int>& sources = sources_;
  std::vector<int>& targets = targets_;
  faces_of_point(mesh_, a, sources);
  faces_of_point(mesh_, b, targets);
  for (int s : sources) {
    if (std::find(targets.begin(), targets.end(), s) != targets.end()) {
      strip.push_back(s);
      return true;
    }
  }
  const Vec3 pa = eval_position(mesh_, a);
  const Vec3 pb = eval_position(mesh_, b);
  const double weight = dual ? dual_heuristic_weight_ : 1.0;
  RingDeque& queue = queue_;
  queue.clear();
  visits_.clear();
  double key_sum = 0;  // sum of (dist + heuristic) over queued nodes, for LLL
  // The record of a node (made on first touch: its position is looked at many times).
  auto visit = [&](int node) -> Visit& {
    int& slot = slot_[node];
    if (slot < 0) {
      const Vec3 p = node_position(node);
      slot = static_cast<int>(visits_.size());
      visits_.push_back({std::numeric_limits<float>::infinity(), static_cast<float>(weight * (p - pb).norm()), node, -1,
                         p.cast<float>(), false});
    }
    return visits_[slot];
  };
  auto key = [&](const Visit& v) { return v.dist + v.heuristic; };
  // Relaxes `node` from `from`; SLF puts improved nodes at the front or the back of the deque.
  auto relax = [&](int node, int from, float d) {
    Visit& v = visit(node);
    if (d >= v.dist) return;
    if (v.queued) {
      key_sum -= v.dist - d;
    } else {
      key_sum += d + v.heuristic;
      v.queued = true;
      if (!queue.empty() && d + v.heuristic < key(visits_[queue.front()]))
        queue.push_front(slot_[node]);
      else
        queue.push_back(slot_[node]);
    }
    v.dist = d;
    v.parent = from;
  };
  // The nodes of face f: its centroid and the nodes on its edges (but those on `skip_edge`).
  auto for_face_nodes = [&](int f, int skip_edge, auto&& each) {
    each(f);
    if (dual) return;
    for (int k = 0; k < 3; ++k) {
      const int e = graph_.halfedge_edge[3 * f + k];
      if (e == skip_edge) continue;
      for (int n = graph_.first_node(e), end = graph_.end_node(e); n < end; ++n) each(n);
    }
  };
  auto is_target = [&](int f) { return std::find(targets.begin(), targets.end(), f) != targets.end(); };
  // Best arrival into a target face so far: from node, into face, total length.
  int best_node = -1, best_face = -1;
  float best = std::numeric_limits<float>::infinity();

  for (int s : sources)
    for_face_nodes(s, -1, [&](int node) {
      relax(node, -1, static_cast<float>((visit(node).position.cast<double>() - pa).norm()));
    });

  int visited = 0;
  while (!queue.empty()) {
    // LLL: nodes whose key exceeds the queue's mean go to the back (the deque holds records).
    const double mean = key_sum / static_cast<double>(queue.size());
    for (size_t moves = 0; moves < queue.size(); ++moves) {
      const int r = queue.front();
      if (key(visits_[r]) <= mean) break;
      queue.pop_front();
      queue.push_back(r);
    }
    const int r = queue.pop_front();
    visits_[r].queued = false;
    key_sum -= key(visits_[r]);
    // A* bound: a node whose key reaches the best arrival cannot improve it (the deque is not a
    // priority queue, so the search drains it instead of stopping at the first such node).
    if (key(visits_[r]) >= best) {
      if (dual) break;
      continue;
    }
    ++visited;
    // (copies: visit() may grow visits_)
    const int u = visits_[r].node;
    const float du = visits_[r].dist, hu = visits_[r].heuristic;
    const Eigen::Vector3f pu = visits_[r].position;
    auto arrive = [&](int f) {
      if (is_target(f) && du + hu < best) best = du + hu, best_node = u, best_face = f;
    };
    auto expand_face = [&](int f, int skip_edge) {
      arrive(f);
      for_face_nodes(f, skip_edge, [&](int node) {
        if (node != u) relax(node, u, du + (visit(node).position - pu).norm());
      });
    };
    if (dual) {
      arrive(u);
      for (int g : mesh_.adjacency[u])
        if (g >= 0) relax(g, u, du + (visit(g).position - pu).norm());
    } else if (u < nf) {
      expand_face(u, -1);
    } else {
      int faces[2];
      node_faces(mesh_, graph_, u, faces);
      const int e = graph_.edge_of_node(u);
      for (int f : faces)
        if (f >= 0) expand_face(f, e);
    }
  }
  if (stats) stats->visited_nodes += visited;

  auto parent = [&](int node) { return visits_[slot_[node]].parent; };
  if (best_face >= 0) {
    // Walk back: face nodes contribute their face, links the face they run through.
    strip.push_back(best_face);
    for (int node = best_node; node >= 0; node = parent(node)) {
      if (node < nf) {
        strip.push_back(node);
      } else {
        int faces[2];
        node_faces(mesh_, graph_, node, faces);
        const int f = strip.back();
        // An edge node between the face after it and the face before it in the strip.
        const int before = parent(node) >= 0 ? link_face(node, parent(node)) : -1;
        if (faces[0] != f && faces[1] != f) strip.push_back(faces[0] == before ? faces[1] : faces[0]);
        if (before >= 0) strip.push_back(before);
      }
    }
    // The first node was linked to the source point through a source face.
    {
      int first = best_node;
      while (first >= 0 && parent(first) >= 0) first = parent(first);
      int faces[2];
      if (first >= nf) {
        node_faces(mesh_, graph_, first, faces);
        const int src = std::find(sources.begin(), sources.end(), faces[0]) != sources.end() ? faces[0] : faces[1];
        if (strip.back() != src) strip.push_back(src);
      }
    }
    std::reverse(strip.begin(), strip.end());
    strip.erase(std::unique(strip.begin(), strip.end()), strip.end());
  }
  for (const Visit& v : visits_) slot_[v.node] = -1;
  visits_.clear();
  // A long refined search can touch most of the graph; its records are not kept beyond 2 MB.
  if (visits_.capacity() > (size_t{1} << 16)) visits_ = std::vector<Visit>();
  if (best_face < 0) return false;
  remove_loops(strip, slot_);
  return true;
}

}  // namespace splinekit::surface
