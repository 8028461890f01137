// The subdivision-surface skinning rig (wasm/core/skin3d/rig.h): exact reproduction of the cage
// under the identity and under a transform shared by every handle, optimality of the fit (no
// perturbation lowers the energy, never worse than the naive baseline), and allocation-free
// updates.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>

#include "skin3d/rig.h"
#include "test_cages.h"

// Counts every operator new in the process (the update must not call it).
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace splinekit::skin3d {
namespace {

using namespace test_cages;

// Farthest-point handles on the cage vertices, starting at vertex 0.
std::vector<double> farthest_handles(const Cage& c, int count) {
  std::vector<double> d(c.nv(), INFINITY), h;
  int pick = 0;
  for (int k = 0; k < count; ++k) {
    h.insert(h.end(), {c.V[3 * pick], c.V[3 * pick + 1], c.V[3 * pick + 2]});
    int best = 0;
    for (int v = 0; v < c.nv(); ++v) {
      d[v] = std::min(d[v], std::hypot(c.V[3 * v] - c.V[3 * pick], c.V[3 * v + 1] - c.V[3 * pick + 1],
                                       c.V[3 * v + 2] - c.V[3 * pick + 2]));
      if (d[v] > d[best]) best = v;
    }
    pick = best;
  }
  return h;
}

void make_rig(const Cage& c, int levels, int handles, SubdivisionRig& rig) {
  ASSERT_EQ(rig.setup(c.V.data(), c.nv(), c.sizes.data(), c.nf(), c.indices.data(), c.creases.data(),
                      int(c.creases.size()), levels, handles),
            "");
  const std::vector<double> h = farthest_handles(c, handles);
  rig.use_shepard(h.data(), 2.0);
  ASSERT_EQ(rig.precompute(), "");
}

// A rotation of up to `max_angle` about a random axis through `centre`, plus a small translation.
void random_transform(std::mt19937& rng, const double* centre, double max_angle, double shift, double* t) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Vector3d axis(u(rng), u(rng), u(rng));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(max_angle * u(rng), axis.normalized()).toRotationMatrix();
  const Eigen::Vector3d c(centre[0], centre[1], centre[2]);
  const Eigen::Vector3d tr = c - R * c + shift * Eigen::Vector3d(u(rng), u(rng), u(rng));
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) t[4 * r + k] = R(r, k);
    t[4 * r + 3] = tr[r];
  }
}

double diagonal(const Cage& c) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (int v = 0; v < c.nv(); ++v) {
    const Eigen::Vector3d p(c.V[3 * v], c.V[3 * v + 1], c.V[3 * v + 2]);
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

TEST(SubdivisionRig, IdentityAndSharedTransformReproduceTheCage) {
  for (const char* name : {"cube_quad.obj", "torus_quad.obj", "catmark_cube_creases1.obj", "spot_control_mesh.obj"}) {
    const Cage c = read_cage(name);
    SubdivisionRig rig;
    make_rig(c, 2, 4, rig);
    const double scale = diagonal(c);
    std::vector<double> T(12 * 4, 0.0);
    for (int i = 0; i < 4; ++i) T[12 * i] = T[12 * i + 5] = T[12 * i + 10] = 1;
    const double* X = rig.update(T.data());
    for (int k = 0; k < 3 * c.nv(); ++k)
      ASSERT_NEAR(X[k], c.V[k], 1e-9 * scale) << name << " identity, coordinate " << k;
    // One affine transform (rotation, shear, translation) for every handle.
    const double A[12] = {0.8, -0.5, 0.1, 0.3, 0.5, 0.9, -0.2, -1.0, 0.05, 0.2, 1.1, 2.0};
    for (int i = 0; i < 4; ++i) std::copy(A, A + 12, &T[12 * i]);
    X = rig.update(T.data());
    for (int v = 0; v < c.nv(); ++v)
      for (int r = 0; r < 3; ++r) {
        const double* p = &c.V[3 * v];
        const double want = A[4 * r] * p[0] + A[4 * r + 1] * p[1] + A[4 * r + 2] * p[2] + A[4 * r + 3];
        ASSERT_NEAR(X[3 * v + r], want, 1e-9 * scale) << name << " shared transform, vertex " << v;
      }
    EXPECT_NEAR(rig.error(X, T.data(), nullptr), 0.0, 1e-10) << name;
  }
}

TEST(SubdivisionRig, FitIsTheEnergyMinimumAndBeatsNaiveOnEveryCage) {
  std::mt19937 rng(18);
  for (const char* name : kSharedCages) {
    const Cage c = read_cage(name);
    SubdivisionRig rig;
    const int H = 4;
    make_rig(c, 2, H, rig);
    const std::vector<double> handles = farthest_handles(c, H);
    for (int pose = 0; pose < 3; ++pose) {
      std::vector<double> T(12 * H);
      for (int i = 0; i < H; ++i) random_transform(rng, &handles[3 * i], 1.047, 0.05 * diagonal(c), &T[12 * i]);
      const std::vector<double> fit(rig.update(T.data()), rig.update(T.data()) + 3 * c.nv());
      const std::vector<double> naive(rig.naive(T.data()), rig.naive(T.data()) + 3 * c.nv());
      const double e_fit = rig.error(fit.data(), T.data(), nullptr),
                   e_naive = rig.error(naive.data(), T.data(), nullptr);
      EXPECT_LT(e_fit, e_naive) << name << " pose " << pose;
      // Optimality: moving the fit in a random direction (or toward naive) never lowers the energy.
      std::normal_distribution<double> g(0, 1);
      for (int trial = 0; trial < 4; ++trial) {
        std::vector<double> moved = fit;
        for (size_t k = 0; k < moved.size(); ++k)
          moved[k] += trial == 0 ? 0.01 * (naive[k] - fit[k]) : 1e-3 * diagonal(c) * g(rng);
        EXPECT_GE(rig.error(moved.data(), T.data(), nullptr), e_fit * (1 - 1e-12)) << name << " pose " << pose;
      }
    }
  }
}

TEST(SubdivisionRig, UpdateAllocatesNothing) {
  const Cage c = read_cage("spot_control_mesh.obj");
  SubdivisionRig rig;
  make_rig(c, 2, 4, rig);
  std::vector<double> T(48, 0.0);
  for (int i = 0; i < 4; ++i) T[12 * i] = T[12 * i + 5] = T[12 * i + 10] = 1, T[12 * i + 3] = 0.01 * i;
  const double* first = rig.update(T.data());
  const long before = g_allocations.load();
  for (int k = 0; k < 1000; ++k) {
    T[3] = 1e-3 * k;
    ASSERT_EQ(rig.update(T.data()), first);
  }
  EXPECT_EQ(g_allocations.load(), before);
}

TEST(SubdivisionRig, ReportsMemoryAndCounts) {
  const Cage c = read_cage("cube_quad.obj");
  SubdivisionRig rig;
  make_rig(c, 3, 2, rig);
  // Refined vertex counts of a closed quad mesh: V_k = V + E + F per level (8 → 26 → 98 → 386).
  EXPECT_EQ(rig.refined_vertex_count(), 386);
  EXPECT_EQ(rig.refined_triangles().size(), size_t(6 * 64 * 2 * 3));
  EXPECT_EQ(rig.memory_O(), size_t(8 * 4 * 2 * sizeof(double)));
  EXPECT_GT(rig.memory_M(), size_t(0));
  // The refined rest surface's area approaches the limit surface's (below the cage's 24).
  double area = 0;
  for (double a : rig.areas()) area += a;
  EXPECT_GT(area, 8.0);
  EXPECT_LT(area, 24.0);
}

TEST(SubdivisionRig, RejectsBadInput) {
  SubdivisionRig rig;
  const double V[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, NAN, 1, 0};
  const int sizes[1] = {4}, quad[4] = {0, 1, 2, 3};
  EXPECT_NE(rig.setup(V, 4, sizes, 1, quad, nullptr, 0, 2, 1).find("vertex 4 has a non-finite coordinate"),
            std::string::npos);
  const double W[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  EXPECT_NE(rig.setup(W, 4, sizes, 1, quad, nullptr, 0, 5, 1).find("levels"), std::string::npos);
  EXPECT_NE(rig.setup(W, 4, sizes, 1, quad, nullptr, 0, 2, 0).find("handle"), std::string::npos);
  const Corner far{4, 1.0};
  EXPECT_NE(rig.setup(W, 4, sizes, 1, quad, nullptr, 0, 2, 1, &far, 1).find("corner tag 1 names vertex 4"),
            std::string::npos);
  ASSERT_EQ(rig.setup(W, 4, sizes, 1, quad, nullptr, 0, 2, 1), "");
  rig.refined_weights()[0] = NAN;
  EXPECT_NE(rig.precompute().find("non-finite"), std::string::npos);
}

}  // namespace
}  // namespace splinekit::skin3d
