// Bounded biharmonic weights on a subdivision surface (wasm/core/skin3d/weights.h) and the 3D
// operators they use (skin/operators.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <utility>
#include <vector>

#include "../skin/test_meshes.h"
#include "skin/operators.h"
#include "skin3d/weights.h"
#include "test_cages.h"

namespace splinekit::skin3d {
namespace {

using namespace test_cages;

TEST(SurfaceOperators, PlanarMeshIn3DMatchesThe2DOperators) {
  // The same jittered grid in the plane and rotated into 3D: cotangents and areas are intrinsic.
  const skin::test_meshes::Mesh flat = skin::test_meshes::grid_mesh(6, true);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<double> V3;
  for (int v = 0; v < flat.nv(); ++v) {
    const Eigen::Vector3d p = R * Eigen::Vector3d(flat.V[2 * v], flat.V[2 * v + 1], 0) + Eigen::Vector3d(1, -2, 0.5);
    V3.insert(V3.end(), {p.x(), p.y(), p.z()});
  }
  const skin::MeshView3 mesh{V3.data(), flat.nv(), flat.F.data(), flat.nf()};
  Eigen::SparseMatrix<double> L2, L3, M2, M3;
  skin::cotangent_laplacian(flat.view(), L2);
  skin::cotangent_laplacian_3d(mesh, L3);
  EXPECT_LT((Eigen::MatrixXd(L2) - Eigen::MatrixXd(L3)).cwiseAbs().maxCoeff(), 1e-12);
  for (auto type : {skin::MassType::kBarycentric, skin::MassType::kVoronoi}) {
    skin::mass_matrix(flat.view(), type, M2);
    skin::mass_matrix_3d(mesh, type, M3);
    EXPECT_LT((Eigen::MatrixXd(M2) - Eigen::MatrixXd(M3)).cwiseAbs().maxCoeff(), 1e-14);
  }
}

TEST(SurfaceBbw, BoundedPartitionOfUnityPeakingAtTheHandles) {
  const Cage torus = read_cage("torus_quad.obj");
  SubdivisionRig rig;
  const int H = 3;
  ASSERT_EQ(
      rig.setup(torus.V.data(), torus.nv(), torus.sizes.data(), torus.nf(), torus.indices.data(), nullptr, 0, 2, H),
      "");
  const double handles[9] = {1.35, 0, 0, -1.35, 0, 0, 0, 0.65, 0};
  const skin::WeightsReport r = surface_bbw_weights(rig, handles, 1, skin::BbwOptions());
  ASSERT_TRUE(r.ok()) << r.error;
  const std::vector<double>& W = rig.refined_weights();
  const std::vector<double>& P = rig.rest_refined();
  for (int v = 0; v < rig.refined_vertex_count(); ++v) {
    double sum = 0;
    for (int i = 0; i < H; ++i) {
      EXPECT_GE(W[v * H + i], -1e-12);
      EXPECT_LE(W[v * H + i], 1 + 1e-12);
      sum += W[v * H + i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
  // Each handle's weight is largest at the refined vertex nearest to it, and dominates there.
  for (int i = 0; i < H; ++i) {
    int nearest = 0;
    double best = INFINITY;
    for (int v = 0; v < rig.refined_vertex_count(); ++v) {
      const double d =
          std::hypot(P[3 * v] - handles[3 * i], P[3 * v + 1] - handles[3 * i + 1], P[3 * v + 2] - handles[3 * i + 2]);
      if (d < best) best = d, nearest = v;
    }
    EXPECT_GT(W[nearest * H + i], 0.9) << "handle " << i;
  }
  // The naive baseline's cage weights are those of each cage vertex's descendant.
  for (int k = 0; k < torus.nv() * H; ++k) EXPECT_EQ(rig.cage_weights()[k], W[k]);
}

TEST(SurfaceBbw, ReportsEachHandleSolvedWithoutChangingTheWeights) {
  const Cage torus = read_cage("torus_quad.obj");
  const int H = 3;
  const double handles[9] = {1.35, 0, 0, -1.35, 0, 0, 0, 0.65, 0};
  std::vector<double> plain, reported;
  std::vector<std::pair<int, int>> calls;
  for (int pass = 0; pass < 2; ++pass) {
    SubdivisionRig rig;
    ASSERT_EQ(
        rig.setup(torus.V.data(), torus.nv(), torus.sizes.data(), torus.nf(), torus.indices.data(), nullptr, 0, 2, H),
        "");
    skin::BbwOptions options;
    if (pass == 1) options.on_handle_solved = [&](int solved, int total) { calls.emplace_back(solved, total); };
    ASSERT_TRUE(surface_bbw_weights(rig, handles, 1, options).ok());
    (pass == 0 ? plain : reported) = rig.refined_weights();
  }
  const std::vector<std::pair<int, int>> expected = {{1, H}, {2, H}, {3, H}};
  EXPECT_EQ(calls, expected);
  EXPECT_EQ(plain, reported);
}

TEST(SurfaceBbw, RejectsHandlesOnOneVertexAndBadLevels) {
  const Cage cube = read_cage("cube_quad.obj");
  SubdivisionRig rig;
  ASSERT_EQ(rig.setup(cube.V.data(), cube.nv(), cube.sizes.data(), cube.nf(), cube.indices.data(), nullptr, 0, 2, 2),
            "");
  const double same[6] = {1, 1, 1, 0.99, 0.99, 0.99};
  EXPECT_NE(surface_bbw_weights(rig, same, 0, skin::BbwOptions()).error.find("snap to the same surface vertex"),
            std::string::npos);
  const double apart[6] = {1, 1, 1, -1, -1, -1};
  EXPECT_NE(surface_bbw_weights(rig, apart, 3, skin::BbwOptions()).error.find("level must be in 0..2"),
            std::string::npos);
  EXPECT_TRUE(surface_bbw_weights(rig, apart, 0, skin::BbwOptions()).ok());
  EXPECT_EQ(bbw_level(rig, 30), 1);  // 26 vertices at level 1, 98 at level 2
}

}  // namespace
}  // namespace splinekit::skin3d
