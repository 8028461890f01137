// splinekit — a polygon mesh with its edges, the topology one level of Catmull-Clark
// subdivision works on (subdivision.h).
//
// Faces are n-gons (n ≥ 3) in flat arrays (libigl-style offsets + indices); edges are found from
// the faces, each with its one or two faces and a crease sharpness (OpenSubdiv's convention:
// 0 = smooth, s > 0 = semi-sharp for s levels, +∞ = infinitely sharp; boundary edges are
// infinitely sharp). Vertices keep their incident edges and faces in CSR arrays for the vertex
// rules.
#pragma once

#include <string>
#include <vector>

namespace splinekit::skin3d {

// One crease tag: edge (a, b) (vertex indices, either order) and its sharpness (> 0, +∞ allowed).
struct Crease {
  int a = 0, b = 0;
  double sharpness = 0;
};

// One corner tag (OpenSubdiv's `t corner`): vertex v and its sharpness (> 0, +∞ allowed).
struct Corner {
  int v = 0;
  double sharpness = 0;
};

struct PolyMesh {
  // ---- Faces (input) ----------------------------------------------------------------------------
  int vertex_count = 0;            // #V
  std::vector<int> face_start;     // #F+1 offsets into face_vertices
  std::vector<int> face_vertices;  // concatenated vertex indices of every face

  // ---- Edges (build_topology) -------------------------------------------------------------------
  std::vector<int> edge_vertices;        // #E by 2: endpoints (smaller index first)
  std::vector<int> edge_faces;           // #E by 2: incident faces, −1 for the missing one of a boundary edge
  std::vector<double> edge_sharpness;    // #E: 0 smooth, > 0 crease (+∞ on the boundary)
  std::vector<int> corner_edge;          // per face corner c: the edge from vertex c to the next corner's
  std::vector<double> vertex_sharpness;  // #V: 0, or a corner tag's sharpness (the vertex is a corner)

  // ---- Vertex adjacency (build_topology) ---------------------------------------------------------
  std::vector<int> vertex_edge_start, vertex_edges;  // CSR: edges incident to each vertex
  std::vector<int> vertex_face_start, vertex_faces;  // CSR: faces incident to each vertex

  int face_count() const { return int(face_start.size()) - 1; }
  int face_size(int f) const { return face_start[f + 1] - face_start[f]; }
  int edge_count() const { return int(edge_sharpness.size()); }
  bool boundary_edge(int e) const { return edge_faces[2 * e + 1] < 0; }
  int other_end(int e, int v) const {
    return edge_vertices[2 * e] == v ? edge_vertices[2 * e + 1] : edge_vertices[2 * e];
  }
};

// Builds a PolyMesh from flat faces and checks it: at least one face, every face with ≥ 3
// distinct vertices in [0, #V), no edge shared by more than two faces. Returns "" or a message
// naming the first problem (face or edge, 1-based vertex numbers as in the OBJ file).
//   vertex_count  #V
//   face_sizes    #F sizes
//   face_indices  concatenated 0-based vertex indices (Σ sizes)
std::string make_poly_mesh(int vertex_count, const int* face_sizes, int face_count, const int* face_indices,
                           PolyMesh& mesh);

// Finds the edges and the vertex adjacency of mesh's faces (all sharpness 0, boundary +∞; vertex
// sharpness 0).
// Returns "" or a message naming a non-manifold edge.
std::string build_topology(PolyMesh& mesh);

// Applies crease tags to a mesh with edges: the edge (a, b) gets the tag's sharpness (a boundary
// edge stays +∞). Returns "" or a message naming a tag whose edge is not in the mesh or whose
// sharpness is not positive.
std::string apply_creases(const Crease* creases, int crease_count, PolyMesh& mesh);

// Applies corner tags to a mesh with edges: vertex v gets the tag's sharpness (OpenSubdiv's vertex
// sharpness: s levels as a corner, decaying by one per level; +∞ stays a corner). Returns "" or a
// message naming a tag whose vertex is out of range or whose sharpness is not positive.
std::string apply_corners(const Corner* corners, int corner_count, PolyMesh& mesh);

// The edge between vertices a and b, or −1.
int find_edge(const PolyMesh& mesh, int a, int b);

}  // namespace splinekit::skin3d
