#include "poly_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace splinekit::skin3d {

namespace {

// Counts → CSR offsets (in place into start, size n+1), returns the total.
int offsets_from_counts(std::vector<int>& start) {
  int total = 0;
  for (int& s : start) {
    const int c = s;
    s = total;
    total += c;
  }
  return total;
}

std::string vertex_name(int v) { return std::to_string(v + 1); }

}  // namespace

std::string make_poly_mesh(int vertex_count, const int* face_sizes, int face_count, const int* face_indices,
                           PolyMesh& m) {
  if (vertex_count < 3) return "the cage needs at least 3 vertices, got " + std::to_string(vertex_count);
  if (face_count < 1) return "the cage has no faces";
  m = PolyMesh{};
  m.vertex_count = vertex_count;
  m.face_start.assign(size_t(face_count) + 1, 0);
  int at = 0;
  for (int f = 0; f < face_count; ++f) {
    const int n = face_sizes[f];
    if (n < 3) return "face " + std::to_string(f + 1) + " has " + std::to_string(n) + " vertices, expected at least 3";
    for (int k = 0; k < n; ++k) {
      const int v = face_indices[at + k];
      if (v < 0 || v >= vertex_count)
        return "face " + std::to_string(f + 1) + " refers to vertex " + vertex_name(v) + ", outside 1.." +
               std::to_string(vertex_count);
      for (int j = 0; j < k; ++j)
        if (face_indices[at + j] == v) return "face " + std::to_string(f + 1) + " repeats vertex " + vertex_name(v);
    }
    at += n;
    m.face_start[f + 1] = at;
  }
  m.face_vertices.assign(face_indices, face_indices + at);
  return build_topology(m);
}

std::string build_topology(PolyMesh& m) {
  const int nv = m.vertex_count, nf = m.face_count(), nc = int(m.face_vertices.size());
  // Corners bucketed by the smaller endpoint of their edge; within a bucket, equal larger
  // endpoints are the same edge (buckets hold a vertex's few edges, so the scan is short).
  std::vector<int> bucket_start(size_t(nv) + 1, 0);
  auto edge_of = [&](int f, int k, int& lo, int& hi) {
    const int n = m.face_size(f), a = m.face_vertices[m.face_start[f] + k],
              b = m.face_vertices[m.face_start[f] + (k + 1) % n];
    lo = std::min(a, b), hi = std::max(a, b);
  };
  int lo, hi;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < m.face_size(f); ++k) edge_of(f, k, lo, hi), ++bucket_start[lo];
  offsets_from_counts(bucket_start);
  std::vector<int> bucket(static_cast<size_t>(nc)), fill(bucket_start.begin(), bucket_start.end() - 1);
  std::vector<int> corner_face(static_cast<size_t>(nc));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < m.face_size(f); ++k) {
      edge_of(f, k, lo, hi);
      bucket[fill[lo]++] = m.face_start[f] + k;
      corner_face[m.face_start[f] + k] = f;
    }
  m.corner_edge.assign(size_t(nc), -1);
  m.edge_vertices.clear();
  m.edge_faces.clear();
  for (int v = 0; v < nv; ++v) {
    const int first_edge = int(m.edge_vertices.size()) / 2;
    for (int q = bucket_start[v]; q < bucket_start[v + 1]; ++q) {
      const int c = bucket[q], f = corner_face[c];
      edge_of(f, c - m.face_start[f], lo, hi);
      int e = first_edge;
      while (e < int(m.edge_vertices.size()) / 2 && m.edge_vertices[2 * e + 1] != hi) ++e;
      if (e == int(m.edge_vertices.size()) / 2) {
        m.edge_vertices.insert(m.edge_vertices.end(), {lo, hi});
        m.edge_faces.insert(m.edge_faces.end(), {f, -1});
      } else if (m.edge_faces[2 * e + 1] < 0) {
        m.edge_faces[2 * e + 1] = f;
      } else {
        return "non-manifold edge " + vertex_name(lo) + "-" + vertex_name(hi) + ": shared by more than two faces (" +
               std::to_string(m.edge_faces[2 * e] + 1) + ", " + std::to_string(m.edge_faces[2 * e + 1] + 1) + ", " +
               std::to_string(f + 1) + ")";
      }
      m.corner_edge[c] = e;
    }
  }
  const int ne = int(m.edge_vertices.size()) / 2;
  m.edge_sharpness.assign(size_t(ne), 0.0);
  m.vertex_sharpness.assign(size_t(nv), 0.0);
  for (int e = 0; e < ne; ++e)
    if (m.boundary_edge(e)) m.edge_sharpness[e] = std::numeric_limits<double>::infinity();

  // Vertex → edges and vertex → faces.
  m.vertex_edge_start.assign(size_t(nv) + 1, 0);
  for (int e = 0; e < ne; ++e)
    ++m.vertex_edge_start[m.edge_vertices[2 * e]], ++m.vertex_edge_start[m.edge_vertices[2 * e + 1]];
  m.vertex_edges.resize(size_t(offsets_from_counts(m.vertex_edge_start)));
  fill.assign(m.vertex_edge_start.begin(), m.vertex_edge_start.end() - 1);
  for (int e = 0; e < ne; ++e)
    m.vertex_edges[fill[m.edge_vertices[2 * e]]++] = e, m.vertex_edges[fill[m.edge_vertices[2 * e + 1]]++] = e;
  m.vertex_face_start.assign(size_t(nv) + 1, 0);
  for (int v : m.face_vertices) ++m.vertex_face_start[v];
  m.vertex_faces.resize(size_t(offsets_from_counts(m.vertex_face_start)));
  fill.assign(m.vertex_face_start.begin(), m.vertex_face_start.end() - 1);
  for (int f = 0; f < nf; ++f)
    for (int c = m.face_start[f]; c < m.face_start[f + 1]; ++c) m.vertex_faces[fill[m.face_vertices[c]]++] = f;
  return "";
}

int find_edge(const PolyMesh& m, int a, int b) {
  if (a < 0 || a >= m.vertex_count || b < 0 || b >= m.vertex_count) return -1;
  for (int q = m.vertex_edge_start[a]; q < m.vertex_edge_start[a + 1]; ++q)
    if (m.other_end(m.vertex_edges[q], a) == b) return m.vertex_edges[q];
  return -1;
}

std::string apply_creases(const Crease* creases, int crease_count, PolyMesh& m) {
  for (int k = 0; k < crease_count; ++k) {
    const Crease& c = creases[k];
    if (std::isnan(c.sharpness) || c.sharpness <= 0)
      return "crease tag " + std::to_string(k + 1) + " (" + std::to_string(c.a) + " " + std::to_string(c.b) +
             ") has sharpness " + std::to_string(c.sharpness) + ", expected a positive number";
    const int e = find_edge(m, c.a, c.b);
    if (e < 0)
      return "crease tag " + std::to_string(k + 1) + " names vertices " + std::to_string(c.a) + " " +
             std::to_string(c.b) + " (0-based, as tags count), which are not joined by an edge of the cage";
    if (!m.boundary_edge(e)) m.edge_sharpness[e] = c.sharpness;
  }
  return "";
}

std::string apply_corners(const Corner* corners, int corner_count, PolyMesh& m) {
  for (int k = 0; k < corner_count; ++k) {
    const Corner& c = corners[k];
    if (std::isnan(c.sharpness) || c.sharpness <= 0)
      return "corner tag " + std::to_string(k + 1) + " (vertex " + std::to_string(c.v) + ") has sharpness " +
             std::to_string(c.sharpness) + ", expected a positive number";
    if (c.v < 0 || c.v >= m.vertex_count)
      return "corner tag " + std::to_string(k + 1) + " names vertex " + std::to_string(c.v) +
             " (0-based, as tags count), outside 0.." + std::to_string(m.vertex_count - 1);
    m.vertex_sharpness[c.v] = c.sharpness;
  }
  return "";
}

}  // namespace splinekit::skin3d
