#include "weights.h"

#include <cmath>
#include <numeric>

#include "skin/operators.h"

namespace splinekit::skin3d {

namespace {

int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

int bbw_level(const SubdivisionRig& rig, int max_vertices) {
  int level = 0;
  while (level < rig.levels() && rig.subdivision().step(level).rows() <= max_vertices) ++level;
  return level;
}

skin::WeightsReport surface_bbw_weights(SubdivisionRig& rig, const double* handles, int level,
                                        const skin::BbwOptions& options) {
  skin::WeightsReport report;
  if (level < 0 || level > rig.levels()) {
    report.error = "the BBW level must be in 0.." + std::to_string(rig.levels()) + ", got " + std::to_string(level);
    return report;
  }
  const int H = rig.handle_count();
  // The level-l surface: positions by the first l steps, triangles from its faces (fanned).
  Subdivision coarse;
  PolyMesh faces = rig.cage_mesh();
  std::vector<double> positions = rig.rest_cage();
  if (level > 0) {
    coarse.build(rig.cage_mesh(), level);
    positions.resize(3 * size_t(coarse.refined_vertex_count()));
    coarse.apply(rig.rest_cage().data(), 3, positions.data());
    faces = coarse.refined_mesh();
  }
  const int nv = faces.vertex_count;
  std::vector<int32_t> triangles;
  std::vector<int> parent(static_cast<size_t>(nv));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> used(static_cast<size_t>(nv), 0);
  for (int f = 0; f < faces.face_count(); ++f) {
    const int* v = &faces.face_vertices[faces.face_start[f]];
    for (int k = 1; k + 1 < faces.face_size(f); ++k) triangles.insert(triangles.end(), {v[0], v[k], v[k + 1]});
    for (int k = 0; k < faces.face_size(f); ++k)
      used[v[k]] = 1, parent[find_root(parent, v[k])] = find_root(parent, v[0]);
  }
  // Snap each handle to its nearest vertex of the surface (vertices no face uses are skipped, and
  // left out of the check that every connected part has a handle).
  std::vector<int32_t> snapped(static_cast<size_t>(H));
  for (int i = 0; i < H; ++i) {
    const Vec3 h(handles[3 * i], handles[3 * i + 1], handles[3 * i + 2]);
    double best = INFINITY;
    for (int v = 0; v < nv; ++v) {
      if (!used[v]) continue;
      const double d = (Vec3(positions[3 * size_t(v)], positions[3 * size_t(v) + 1], positions[3 * size_t(v) + 2]) - h)
                           .squaredNorm();
      if (d < best) best = d, snapped[i] = v;
    }
    for (int j = 0; j < i; ++j)
      if (snapped[j] == snapped[i]) {
        report.error = "handles " + std::to_string(j + 1) + " and " + std::to_string(i + 1) +
                       " snap to the same surface vertex at BBW level " + std::to_string(level) +
                       "; move them apart or solve at a finer level";
        return report;
      }
  }
  std::vector<char> has_handle(static_cast<size_t>(nv), 0);
  for (int i = 0; i < H; ++i) has_handle[find_root(parent, snapped[i])] = 1;
  for (int v = 0; v < nv; ++v)
    if (used[v] && !has_handle[find_root(parent, v)]) {
      report.error = "the part of the surface containing vertex " + std::to_string(v + 1) +
                     " has no handle, so its bounded biharmonic weights are undetermined";
      return report;
    }

  // Unused vertices (a cage vertex no face uses) get an isolated row: L = 0 there, mass 1, so
  // the solver sees them as free with no energy; give them uniform weights afterwards.
  const skin::MeshView3 mesh{positions.data(), nv, triangles.data(), int(triangles.size() / 3)};
  Eigen::SparseMatrix<double> L, M;
  skin::cotangent_laplacian_3d(mesh, L);
  skin::mass_matrix_3d(mesh, options.mass, M);
  for (int v = 0; v < nv; ++v)
    if (!used[v]) L.coeffRef(v, v) = -1, M.coeffRef(v, v) = 1;
  std::vector<double> W(size_t(nv) * H);
  report = skin::bbw_weights_from_operators(L, M, snapped.data(), H, options, W.data());
  if (!report.ok()) return report;
  for (int v = 0; v < nv; ++v)
    if (!used[v])
      for (int i = 0; i < H; ++i) W[size_t(v) * H + i] = 1.0 / H;

  // Carry to level k with the remaining steps.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> X =
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(W.data(), nv, H);
  for (int j = level; j < rig.levels(); ++j) X = rig.subdivision().step(j) * X;
  std::copy(X.data(), X.data() + X.size(), rig.refined_weights().begin());
  rig.restrict_refined_weights();
  return report;
}

}  // namespace splinekit::skin3d
