#include "surface/mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace splinekit::surface {

namespace {

// An undirected edge key with the half-edge that carries it.
struct HalfEdge {
  uint64_t key;
  int face;
  int8_t k;
};

uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<uint64_t>(std::min(a, b)), hi = static_cast<uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

// Reverses the winding of face f: (a, b, c) -> (a, c, b). Edges (ab, bc, ca) become (ac, cb, ba),
// i.e. old edges (2, 1, 0).
void flip_face(std::array<int, 3>& t, std::array<int, 3>& adj) {
  std::swap(t[1], t[2]);
  std::swap(adj[0], adj[2]);
}

bool is_degenerate(const std::array<int, 3>& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

// Bits 0, 3, 6, ... of the result are those of x (21 bits): one axis of a 3D Morton code.
uint64_t spread_bits(uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// Renumbers the faces in the Morton order of their centroids and the vertices in the order the
// faces first use them, so that faces close on the surface are mostly close in memory too. Paths
// walk from face to face, and each step reads the next face's corners, neighbours and vertex
// positions: files list faces in whatever order their maker left them (a subdivided mesh puts each
// coarse face's children together but a vertex's coarse and fine neighbours far apart). Measured on
// random whole-surface curves (wasm, each traced by both builds in turn): 5% less trace time on
// spot_loop2_369k, 9.5% on nefertiti; faces and vertices contribute about equally.
void order_for_locality(TriMesh& mesh, const Vec3& lo, double extent) {
  const int nf = static_cast<int>(mesh.triangles.size()), nv = static_cast<int>(mesh.positions.size());
  std::vector<std::pair<uint64_t, int>> keyed(nf);
  constexpr double kCells = (1 << 21) - 1;  // per axis
  const double to_grid = extent > 0 ? kCells / extent : 0;
  auto axis = [&](double x) { return spread_bits(static_cast<uint64_t>(std::clamp(x, 0.0, kCells))); };
  for (int f = 0; f < nf; ++f) {
    const auto& t = mesh.triangles[f];
    const Vec3 c = ((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3 - lo) * to_grid;
    keyed[f] = {axis(c.x()) | axis(c.y()) << 1 | axis(c.z()) << 2, f};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> new_face(nf), new_vertex(nv, -1);
  mesh.file_face.resize(nf);
  int next_vertex = 0;
  for (int i = 0; i < nf; ++i) {
    const int f = keyed[i].second;
    new_face[f] = i;
    mesh.file_face[i] = f;
    for (int v : mesh.triangles[f])
      if (new_vertex[v] < 0) new_vertex[v] = next_vertex++;
  }
  for (int& v : new_vertex)
    if (v < 0) v = next_vertex++;

  std::vector<std::array<int, 3>> triangles(nf), adjacency(nf);
  std::vector<uint8_t> flipped(nf);
  for (int i = 0; i < nf; ++i) {
    const int f = mesh.file_face[i];
    for (int k = 0; k < 3; ++k) {
      triangles[i][k] = new_vertex[mesh.triangles[f][k]];
      adjacency[i][k] = mesh.adjacency[f][k] >= 0 ? new_face[mesh.adjacency[f][k]] : -1;
    }
    flipped[i] = mesh.flipped[f];
  }
  mesh.triangles.swap(triangles);
  mesh.adjacency.swap(adjacency);
  mesh.flipped.swap(flipped);
  std::vector<Vec3> positions(nv);
  std::vector<int> vertex_face(nv), file_vertex(nv);
  for (int v = 0; v < nv; ++v) {
    positions[new_vertex[v]] = mesh.positions[v];
    vertex_face[new_vertex[v]] = new_face[mesh.vertex_face[v]];
    file_vertex[new_vertex[v]] = mesh.file_vertex[v];
  }
  mesh.positions.swap(positions);
  mesh.vertex_face.swap(vertex_face);
  mesh.file_vertex.swap(file_vertex);
  for (int& v : mesh.mesh_vertex)
    if (v >= 0) v = new_vertex[v];
  mesh.mesh_face = std::move(new_face);
}

}  // namespace

MeshStatus build_mesh(const double* positions, int num_vertices, const int* triangles, int num_faces, TriMesh& out,
                      std::string& error) {
  if (num_vertices <= 0) return error = "the mesh has no vertices", MeshStatus::kInvalidInput;
  if (num_faces <= 0) return error = "the mesh has no faces", MeshStatus::kInvalidInput;
  for (int i = 0; i < 3 * num_vertices; ++i) {
    if (!std::isfinite(positions[i])) {
      error = "vertex " + std::to_string(i / 3) + " has a non-finite coordinate";
      return MeshStatus::kInvalidInput;
    }
  }
  for (int i = 0; i < 3 * num_faces; ++i) {
    if (triangles[i] < 0 || triangles[i] >= num_vertices) {
      error = "face " + std::to_string(i / 3) + " refers to vertex " + std::to_string(triangles[i]) +
              ", but the mesh has " + std::to_string(num_vertices) + " vertices";
      return MeshStatus::kInvalidInput;
    }
  }

  TriMesh mesh;
  MeshReport& report = mesh.report;
  report.file_vertices = num_vertices;
  report.file_faces = num_faces;

  // ---- Weld duplicate positions (first occurrence in file order wins) -----------------------------
  std::vector<uint8_t> used(num_vertices, 0);
  for (int i = 0; i < 3 * num_faces; ++i) used[triangles[i]] = 1;
  std::vector<int> order(num_vertices);
  std::iota(order.begin(), order.end(), 0);
  auto less_pos = [&](int a, int b) {
    const double* pa = positions + 3 * a;
    const double* pb = positions + 3 * b;
    if (pa[0] != pb[0]) return pa[0] < pb[0];
    if (pa[1] != pb[1]) return pa[1] < pb[1];
    if (pa[2] != pb[2]) return pa[2] < pb[2];
    return a < b;
  };
  std::sort(order.begin(), order.end(), less_pos);
  std::vector<int> representative(num_vertices);
  for (size_t i = 0; i < order.size();) {
    size_t j = i;
    int first_used = -1;
    const double* pi = positions + 3 * order[i];
    while (j < order.size() && positions[3 * order[j]] == pi[0] && positions[3 * order[j] + 1] == pi[1] &&
           positions[3 * order[j] + 2] == pi[2]) {
      if (used[order[j]] && first_used < 0) first_used = order[j];
      ++j;
    }
    for (size_t m = i; m < j; ++m) {
      const int v = order[m];
      representative[v] = used[v] ? first_used : v;
      if (used[v] && v != first_used) ++report.welded_vertices;
    }
    i = j;
  }
  for (int v = 0; v < num_vertices; ++v) report.unreferenced_vertices += used[v] ? 0 : 1;

  mesh.mesh_vertex.assign(num_vertices, -1);
  for (int v = 0; v < num_vertices; ++v) {
    if (used[v] && representative[v] == v) {
      mesh.mesh_vertex[v] = static_cast<int>(mesh.file_vertex.size());
      mesh.file_vertex.push_back(v);
    }
  }
  for (int v = 0; v < num_vertices; ++v) {
    if (used[v] && representative[v] != v) mesh.mesh_vertex[v] = mesh.mesh_vertex[representative[v]];
  }
  mesh.positions.resize(mesh.file_vertex.size());
  for (size_t i = 0; i < mesh.file_vertex.size(); ++i) {
    const double* p = positions + 3 * mesh.file_vertex[i];
    mesh.positions[i] = Vec3(p[0], p[1], p[2]);
  }
  mesh.triangles.resize(num_faces);
  for (int f = 0; f < num_faces; ++f) {
    for (int k = 0; k < 3; ++k) mesh.triangles[f][k] = mesh.mesh_vertex[triangles[3 * f + k]];
  }
  mesh.flipped.assign(num_faces, 0);

  // ---- Faces that repeat an earlier face's vertices (first occurrence in file order wins) ---------
  // A double-sided mesh lists every face twice (once per winding); left in, the copies would give
  // every edge four faces, and the mesh would fall apart into single faces.
  // Faces left out of the adjacency, the fans and the boundary: degenerate and repeated ones.
  std::vector<uint8_t> isolated(num_faces, 0);
  std::vector<int> repeats(num_faces, -1);  // the earlier face a face repeats, or -1
  {
    std::vector<std::pair<std::array<int, 3>, int>> sorted;
    sorted.reserve(num_faces);
    for (int f = 0; f < num_faces; ++f) {
      std::array<int, 3> t = mesh.triangles[f];
      if (is_degenerate(t)) {
        isolated[f] = 1;
        ++report.degenerate_faces;
        continue;
      }
      std::sort(t.begin(), t.end());
      sorted.push_back({t, f});
    }
    std::sort(sorted.begin(), sorted.end());  // (a group's first entry: its first face in the file)
    for (size_t i = 1, first = 0; i < sorted.size(); ++i) {
      if (sorted[i].first != sorted[first].first) {
        first = i;
        continue;
      }
      repeats[sorted[i].second] = sorted[first].second;
      isolated[sorted[i].second] = 1;
      ++report.duplicate_faces;
    }
  }

  // ---- Adjacency by matching undirected edges -----------------------------------------------------
  mesh.adjacency.assign(num_faces, {-1, -1, -1});
  {
    std::vector<HalfEdge> half_edges;
    half_edges.reserve(3 * static_cast<size_t>(num_faces));
    for (int f = 0; f < num_faces; ++f) {
      const auto& t = mesh.triangles[f];
      if (isolated[f]) continue;
      for (int k = 0; k < 3; ++k) half_edges.push_back({edge_key(t[k], t[(k + 1) % 3]), f, static_cast<int8_t>(k)});
    }
    std::sort(half_edges.begin(), half_edges.end(),
              [](const HalfEdge& a, const HalfEdge& b) { return a.key != b.key ? a.key < b.key : a.face < b.face; });
    for (size_t i = 0; i < half_edges.size();) {
      size_t j = i;
      while (j < half_edges.size() && half_edges[j].key == half_edges[i].key) ++j;
      if (j - i == 2) {
        const HalfEdge& a = half_edges[i];
        const HalfEdge& b = half_edges[i + 1];
        mesh.adjacency[a.face][a.k] = b.face;
        mesh.adjacency[b.face][b.k] = a.face;
      } else if (j - i > 2) {
        ++report.non_manifold_edges;  // every face keeps it as a boundary edge
      }
      i = j;
    }
  }

  // ---- Consistent winding per component (breadth-first; flip neighbours that disagree) ------------
  {
    std::vector<uint8_t> seen(num_faces, 0);
    std::vector<int> queue;
    for (int seed = 0; seed < num_faces; ++seed) {
      if (seen[seed]) continue;
      seen[seed] = 1;
      if (repeats[seed] >= 0) continue;  // (the face it repeats counts)
      ++report.components;
      queue.assign(1, seed);
      for (size_t q = 0; q < queue.size(); ++q) {
        const int f = queue[q];
        for (int k = 0; k < 3; ++k) {
          const int g = mesh.adjacency[f][k];
          if (g < 0) continue;
          const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
          const int kg = edge_to(mesh, g, f);
          // Agreeing windings traverse the shared edge in opposite directions.
          const bool agrees = mesh.triangles[g][kg] == b && mesh.triangles[g][(kg + 1) % 3] == a;
          if (!seen[g]) {
            if (!agrees) {
              flip_face(mesh.triangles[g], mesh.adjacency[g]);
              mesh.flipped[g] ^= 1;
              ++report.flipped_faces;
            }
            seen[g] = 1;
            queue.push_back(g);
          } else if (!agrees) {
            // A Möbius-like strip: no consistent winding exists; cut this adjacency.
            mesh.adjacency[f][k] = -1;
            mesh.adjacency[g][kg] = -1;
            ++report.non_orientable_cuts;
          }
        }
      }
    }
  }

  // ---- Split vertices whose faces form several fans -----------------------------------------------
  const int nv = static_cast<int>(mesh.positions.size());
  {
    std::vector<int> offsets(nv + 1, 0);
    for (int f = 0; f < num_faces; ++f)
      if (!isolated[f])
        for (int v : mesh.triangles[f]) ++offsets[v + 1];
    for (int v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
    std::vector<int> incident(offsets[nv]);
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int f = 0; f < num_faces; ++f)
      if (!isolated[f])
        for (int v : mesh.triangles[f]) incident[fill[v]++] = f;

    mesh.vertex_face.assign(nv, -1);
    std::vector<int> fan;
    std::vector<uint8_t> visited;
    for (int v = 0; v < nv; ++v) {
      const int begin = offsets[v], end = offsets[v + 1];
      visited.assign(end - begin, 0);
      int fans = 0;
      for (int s = begin; s < end; ++s) {
        if (visited[s - begin]) continue;
        // Walk backwards to the start of this fan (a boundary), then forwards collecting it.
        int start = incident[s];
        for (int steps = 0; steps < end - begin; ++steps) {
          const int k = corner_of(mesh, start, v);
          const int prev = mesh.adjacency[start][k];  // across edge (v, next)
          if (prev < 0 || prev == incident[s]) break;
          start = prev;
        }
        fan.clear();
        int f = start;
        for (int steps = 0; steps <= end - begin && f >= 0; ++steps) {
          fan.push_back(f);
          const int k = corner_of(mesh, f, v);
          f = mesh.adjacency[f][(k + 2) % 3];  // across edge (prev, v)
          if (f == start) break;
        }
        int target = v;
        if (fans > 0) {  // a further fan gets its own copy of the vertex
          target = static_cast<int>(mesh.positions.size());
          mesh.positions.push_back(mesh.positions[v]);
          mesh.file_vertex.push_back(mesh.file_vertex[v]);
          mesh.vertex_face.push_back(start);
          if (fans == 1) ++report.non_manifold_vertices;
        } else {
          mesh.vertex_face[v] = start;
        }
        for (int g : fan) {
          for (int m = begin; m < end; ++m)
            if (incident[m] == g) visited[m - begin] = 1;
          if (target != v) mesh.triangles[g][corner_of(mesh, g, v)] = target;
        }
        ++fans;
      }
    }
  }
  // Vertices only used by degenerate faces still need a face.
  for (int f = 0; f < num_faces; ++f)
    for (int v : mesh.triangles[f])
      if (mesh.vertex_face[v] < 0) mesh.vertex_face[v] = f;

  // ---- Boundary statistics and scale --------------------------------------------------------------
  {
    std::vector<std::pair<int, int>> boundary;  // (from, to) along the winding
    for (int f = 0; f < num_faces; ++f) {
      if (isolated[f]) continue;
      for (int k = 0; k < 3; ++k)
        if (mesh.adjacency[f][k] < 0) boundary.emplace_back(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3]);
    }
    report.boundary_edges = static_cast<int>(boundary.size());
    // Loops: connected components of the boundary edges (union-find over vertices).
    std::vector<int> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    std::vector<uint8_t> on_boundary(mesh.positions.size(), 0);
    for (auto [a, b] : boundary) {
      on_boundary[a] = on_boundary[b] = 1;
      parent[find(a)] = find(b);
    }
    for (size_t v = 0; v < parent.size(); ++v)
      report.boundary_loops += on_boundary[v] && find(static_cast<int>(v)) == static_cast<int>(v);
  }
  Vec3 lo = mesh.positions[0], hi = mesh.positions[0];
  for (const Vec3& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  mesh.scale = std::max((hi - lo).norm(), 1e-300);
  mesh.centre = (lo + hi) / 2;
  order_for_locality(mesh, lo, (hi - lo).maxCoeff());
  for (int f = 0; f < num_faces; ++f)
    if (repeats[f] >= 0) mesh.duplicates.emplace_back(mesh.mesh_face[f], mesh.mesh_face[repeats[f]]);
  std::sort(mesh.duplicates.begin(), mesh.duplicates.end());
  report.used_vertices = static_cast<int>(mesh.positions.size());
  out = std::move(mesh);
  return MeshStatus::kOk;
}

size_t mesh_bytes(const TriMesh& m) {
  return m.positions.capacity() * sizeof(Vec3) + m.triangles.capacity() * sizeof(m.triangles[0]) +
         m.adjacency.capacity() * sizeof(m.adjacency[0]) +
         (m.vertex_face.capacity() + m.file_vertex.capacity() + m.mesh_vertex.capacity()) * sizeof(int) +
         m.flipped.capacity() + (m.file_face.capacity() + m.mesh_face.capacity()) * sizeof(int) +
         m.duplicates.capacity() * sizeof(m.duplicates[0]);
}

Vec3 eval_position(const TriMesh& mesh, const MeshPoint& p) {
  const auto& t = mesh.triangles[p.face];
  return (1 - p.uv.x() - p.uv.y()) * mesh.positions[t[0]] + p.uv.x() * mesh.positions[t[1]] +
         p.uv.y() * mesh.positions[t[2]];
}

Vec3 face_normal(const TriMesh& mesh, int face) {
  const auto& t = mesh.triangles[face];
  const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
  const double len = n.norm();
  return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

MeshPoint to_mesh_point(const TriMesh& mesh, const MeshPoint& p) {
  const int f = mesh.mesh_face[p.face];
  const MeshPoint on_f = mesh.flipped[f] ? MeshPoint{f, Vec2(p.uv.y(), p.uv.x())} : MeshPoint{f, p.uv};
  if (mesh.duplicates.empty()) return on_f;
  const auto d = std::lower_bound(mesh.duplicates.begin(), mesh.duplicates.end(), std::make_pair(f, -1));
  if (d == mesh.duplicates.end() || d->first != f) return on_f;
  // The same vertices (welded, never split: a duplicate is in no fan) in the first face's order.
  const int g = d->second;
  const Eigen::Vector3d w = weights(on_f);
  Eigen::Vector3d on_g = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const int c = corner_of(mesh, g, mesh.triangles[f][k]);
    if (c < 0) return on_f;  // (g's vertex was split off as non-manifold: the copy stays apart)
    on_g[c] = w[k];
  }
  return from_weights(g, on_g);
}

MeshPoint to_file_point(const TriMesh& mesh, const MeshPoint& p) {
  if (mesh.flipped[p.face]) return {mesh.file_face[p.face], Vec2(p.uv.y(), p.uv.x())};
  return {mesh.file_face[p.face], p.uv};
}

MeshPoint vertex_point(const TriMesh& mesh, int vertex) { return corner_point(mesh, mesh.vertex_face[vertex], vertex); }

MeshPoint corner_point(const TriMesh& mesh, int face, int vertex) {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  w[corner_of(mesh, face, vertex)] = 1;
  return from_weights(face, w);
}

PointLocation locate(const TriMesh& mesh, const MeshPoint& p, double eps) {
  const Eigen::Vector3d w = weights(p);
  for (int k = 0; k < 3; ++k)
    if (w[k] > 1 - eps) return {PointLocation::Kind::kVertex, mesh.triangles[p.face][k]};
  for (int k = 0; k < 3; ++k)
    if (w[k] < eps) return {PointLocation::Kind::kEdge, (k + 1) % 3};  // the edge opposite corner k
  return {};
}

bool point_in_face(const TriMesh& mesh, const MeshPoint& p, int face, MeshPoint& out, double eps) {
  if (face == p.face) return out = p, true;
  const PointLocation where = locate(mesh, p, eps);
  if (where.kind == PointLocation::Kind::kVertex) {
    const int k = corner_of(mesh, face, where.index);
    if (k < 0) return false;
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    w[k] = 1;
    out = from_weights(face, w);
    return true;
  }
  if (where.kind == PointLocation::Kind::kEdge && mesh.adjacency[p.face][where.index] == face) {
    const Eigen::Vector3d w = weights(p);
    const auto& t = mesh.triangles[p.face];
    const int a = t[where.index], b = t[(where.index + 1) % 3];
    const double s = w[(where.index + 1) % 3] / std::max(w[where.index] + w[(where.index + 1) % 3], 1e-300);
    Eigen::Vector3d wf = Eigen::Vector3d::Zero();
    wf[corner_of(mesh, face, a)] = 1 - s;
    wf[corner_of(mesh, face, b)] = s;
    out = from_weights(face, wf);
    return true;
  }
  return false;
}

void vertex_fan(const TriMesh& mesh, int v, std::vector<int>& faces, bool& closed) {
  faces.clear();
  closed = false;
  const int start = mesh.vertex_face[v];
  int f = start;
  for (size_t guard = 0; guard < mesh.triangles.size() && f >= 0; ++guard) {
    faces.push_back(f);
    const int k = corner_of(mesh, f, v);
    if (k < 0) break;
    f = mesh.adjacency[f][(k + 2) % 3];
    if (f == start) {
      closed = true;
      break;
    }
  }
}

}  // namespace splinekit::surface
