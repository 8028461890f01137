// Triangle meshes for b/Surf (Mancinelli, Nazzaro, Pellacini, Puppo, "b/Surf: interactive Bézier
// splines on surface meshes", §5.1 "Data representation"): an indexed mesh, its face adjacency (which
// is also the dual graph), and the repairs a user expects when opening real files.
//
// Everything here is plain data over flat arrays. Two index spaces exist:
//   - file space: vertex and face indices as in the file the user opened (what the API speaks);
//   - mesh space: after welding duplicate positions, dropping unreferenced vertices, orienting faces
//     consistently and splitting non-manifold vertices, faces and vertices renumbered so that
//     neighbours on the surface are mostly neighbours in memory (what the algorithms use).
// Every file face is a mesh face (file_face / mesh_face map between the two); its winding may be
// flipped (`flipped[f]`), which swaps the barycentric coordinates of points on it (to_mesh_point /
// to_file_point). A face on the same vertices as an earlier one (a double-sided mesh's second side)
// stays a mesh face but out of the adjacency; to_mesh_point moves points on it to the earlier face.
#pragma once

#include "common/geometry.h"  // Vec2, Vec3 (and kPi, cross, orient) for the whole surface core

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace splinekit::surface {

// A point on the mesh: a face and barycentric coordinates (u, v) with respect to its vertices
// (p = (1-u-v)·p0 + u·p1 + v·p2).
struct MeshPoint {
  int face = -1;
  Vec2 uv = Vec2::Zero();
};

// What happened while building the mesh; all counts in file space unless noted.
struct MeshReport {
  int file_vertices = 0;
  int file_faces = 0;
  int used_vertices = 0;          // mesh-space vertices (after welding and splitting)
  int welded_vertices = 0;        // file vertices merged into an earlier one at the same position
  int unreferenced_vertices = 0;  // file vertices no face uses
  int degenerate_faces = 0;       // faces with a repeated vertex (after welding): kept, isolated
  int duplicate_faces = 0;        // faces on the vertices of an earlier face (after welding; a double-sided
                                  // mesh lists each face twice): kept, isolated, their points moved to it
  int non_manifold_edges = 0;     // edges with more than two faces: left as boundaries
  int non_manifold_vertices = 0;  // vertices whose faces form several fans: given one copy per fan
  int flipped_faces = 0;          // faces whose winding was reversed to agree with their neighbours
  int non_orientable_cuts = 0;    // adjacencies cut because no consistent winding exists
  int boundary_edges = 0;
  int boundary_loops = 0;
  int components = 0;
};

// The report's counts by name, in one fixed order: the one list of them that crosses to TypeScript
// (the bindings hand it on as an object, src/surface/mesh.ts reads the counts by these names, so
// no other layer restates their order).
inline std::array<std::pair<const char*, int>, 14> report_fields(const MeshReport& r) {
  return {{{"file_vertices", r.file_vertices},
           {"file_faces", r.file_faces},
           {"used_vertices", r.used_vertices},
           {"welded_vertices", r.welded_vertices},
           {"unreferenced_vertices", r.unreferenced_vertices},
           {"degenerate_faces", r.degenerate_faces},
           {"duplicate_faces", r.duplicate_faces},
           {"non_manifold_edges", r.non_manifold_edges},
           {"non_manifold_vertices", r.non_manifold_vertices},
           {"flipped_faces", r.flipped_faces},
           {"non_orientable_cuts", r.non_orientable_cuts},
           {"boundary_edges", r.boundary_edges},
           {"boundary_loops", r.boundary_loops},
           {"components", r.components}}};
}

struct TriMesh {
  std::vector<Vec3> positions;                // #V mesh-space vertices
  std::vector<std::array<int, 3>> triangles;  // #F faces (mesh order), consistently wound
  std::vector<std::array<int, 3>> adjacency;  // face across edge (t[k], t[k+1]); -1 on a boundary
  std::vector<int> vertex_face;               // #V one face of each vertex; a fan's first face on a boundary
  std::vector<int> file_vertex;               // #V mesh vertex -> file vertex
  std::vector<int> mesh_vertex;               // #file vertices: file vertex -> mesh vertex (-1 unused)
  std::vector<int> file_face;                 // #F mesh face -> file face
  std::vector<int> mesh_face;                 // #F file face -> mesh face
  std::vector<uint8_t> flipped;               // #F 1 when the (mesh) face's winding was reversed
  // (duplicate, first) mesh faces, by duplicate: a face on the same vertices as an earlier one in the
  // file (to_mesh_point moves points from the duplicate to the first, which alone has neighbours).
  std::vector<std::pair<int, int>> duplicates;
  double scale = 1;            // bounding-box diagonal
  Vec3 centre = Vec3::Zero();  // bounding-box centre
  MeshReport report;
};

enum class MeshStatus { kOk, kInvalidInput };

// Builds a mesh from file arrays. positions: #file_vertices x 3; triangles: #faces x 3 file indices.
// On kInvalidInput, `error` names the problem and `mesh` is left untouched.
MeshStatus build_mesh(const double* positions, int num_vertices, const int* triangles, int num_faces, TriMesh& mesh,
                      std::string& error);

// Bytes held by the mesh's arrays.
size_t mesh_bytes(const TriMesh& mesh);

// ---- Points -------------------------------------------------------------------------------------

Vec3 eval_position(const TriMesh& mesh, const MeshPoint& p);
Vec3 face_normal(const TriMesh& mesh, int face);  // unit (zero for a degenerate face)
// Barycentric weights (w0, w1, w2) of a point.
inline Eigen::Vector3d weights(const MeshPoint& p) { return {1 - p.uv.x() - p.uv.y(), p.uv.x(), p.uv.y()}; }
inline MeshPoint from_weights(int face, const Eigen::Vector3d& w) { return {face, Vec2(w[1], w[2])}; }

// File space <-> mesh space (the face renumbered; the winding of flipped faces swaps u and v; a
// point on a duplicate face becomes the same point on the face it repeats).
MeshPoint to_mesh_point(const TriMesh& mesh, const MeshPoint& file_point);
MeshPoint to_file_point(const TriMesh& mesh, const MeshPoint& mesh_point);
// A mesh vertex as a point on its vertex_face (or on `face`, one of its faces).
MeshPoint vertex_point(const TriMesh& mesh, int vertex);
MeshPoint corner_point(const TriMesh& mesh, int face, int vertex);

// Index (0..2) of vertex v in face f, or -1.
inline int corner_of(const TriMesh& mesh, int face, int vertex) {
  const auto& t = mesh.triangles[face];
  return t[0] == vertex ? 0 : t[1] == vertex ? 1 : t[2] == vertex ? 2 : -1;
}
// Index (0..2) of the edge of `face` shared with `neighbor`, or -1.
inline int edge_to(const TriMesh& mesh, int face, int neighbor) {
  const auto& a = mesh.adjacency[face];
  return a[0] == neighbor ? 0 : a[1] == neighbor ? 1 : a[2] == neighbor ? 2 : -1;
}

// Where a point sits: inside its face, on an edge (edge index), or on a vertex (mesh vertex).
struct PointLocation {
  enum class Kind { kFace, kEdge, kVertex };
  Kind kind = Kind::kFace;
  int index = -1;  // edge index in the face (kEdge) or mesh vertex (kVertex)
};
PointLocation locate(const TriMesh& mesh, const MeshPoint& p, double eps = 1e-9);

// The same point expressed on `face` (which must contain it: same face, across its edge, or around
// its vertex). Returns false when `face` does not contain the point.
bool point_in_face(const TriMesh& mesh, const MeshPoint& p, int face, MeshPoint& out, double eps = 1e-9);

// Faces around mesh vertex v in fan order (following the adjacency across the edge that ends at v).
// `closed` tells whether the fan wraps around (interior vertex) or runs boundary to boundary.
void vertex_fan(const TriMesh& mesh, int v, std::vector<int>& faces, bool& closed);

}  // namespace splinekit::surface
