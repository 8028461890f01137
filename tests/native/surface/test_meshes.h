// Small meshes with known geometry for the surface tests: planar grids, a cube, a cylinder, tubes
// (a coil, a knotted tube, a body with folded limbs), noise, and a reader for the shared OBJ/PLY
// test data.
#pragma once

#include "../reference/exact_geodesic.h"
#include "surface/mesh.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace splinekit::surface::testing {

struct Arrays {
  std::vector<double> positions;
  std::vector<int> triangles;
  int vertices() const { return static_cast<int>(positions.size() / 3); }
  int faces() const { return static_cast<int>(triangles.size() / 3); }
};

inline TriMesh build(const Arrays& a) {
  TriMesh mesh;
  std::string error;
  if (build_mesh(a.positions.data(), a.vertices(), a.triangles.data(), a.faces(), mesh, error) != MeshStatus::kOk)
    throw std::runtime_error(error);
  return mesh;
}

// The exact polyhedral geodesic distances (MMP, tests/native/reference) on a built mesh's own
// vertices and faces.
inline reference::ExactGeodesic exact_geodesic(const TriMesh& mesh) {
  std::vector<double> positions;
  std::vector<int> triangles;
  for (const Vec3& p : mesh.positions) positions.insert(positions.end(), {p.x(), p.y(), p.z()});
  for (const auto& t : mesh.triangles) triangles.insert(triangles.end(), {t[0], t[1], t[2]});
  return reference::ExactGeodesic(positions.data(), static_cast<int>(mesh.positions.size()), triangles.data(),
                                  static_cast<int>(mesh.triangles.size()));
}

// An n x n grid over [0, size]^2 in the plane z = 0 with interior vertices jittered by `jitter`
// cells and alternating diagonals.
inline Arrays planar_grid(int n, double size = 1, double jitter = 0.25, unsigned seed = 7) {
  Arrays a;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  const double h = size / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool interior = i > 0 && j > 0 && i < n && j < n;
      a.positions.insert(a.positions.end(),
                         {h * (i + (interior ? u(rng) : 0)), h * (j + (interior ? u(rng) : 0)), 0.0});
    }
  auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a00 = id(i, j), a10 = id(i + 1, j), a01 = id(i, j + 1), a11 = id(i + 1, j + 1);
      if ((i + j) % 2 == 0) {
        a.triangles.insert(a.triangles.end(), {a00, a10, a11, a00, a11, a01});
      } else {
        a.triangles.insert(a.triangles.end(), {a00, a10, a01, a10, a11, a01});
      }
    }
  return a;
}

// The surface of the cube [0, 1]^3, each face an n x n grid.
inline Arrays cube(int n) {
  Arrays a;
  std::vector<std::array<double, 3>> pts;
  auto vertex = [&](double x, double y, double z) {
    for (size_t i = 0; i < pts.size(); ++i)
      if (std::abs(pts[i][0] - x) + std::abs(pts[i][1] - y) + std::abs(pts[i][2] - z) < 1e-12)
        return static_cast<int>(i);
    pts.push_back({x, y, z});
    return static_cast<int>(pts.size() - 1);
  };
  // Each face: origin o, axes u, v with u x v pointing outwards.
  const double faces[6][9] = {{0, 0, 0, 0, 1, 0, 1, 0, 0}, {0, 0, 1, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 0, 0, 0, 0, 1},
                              {0, 1, 0, 0, 0, 1, 1, 0, 0}, {0, 0, 0, 0, 0, 1, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}};
  for (const auto& f : faces) {
    std::vector<int> ids((n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double s = double(i) / n, t = double(j) / n;
        ids[j * (n + 1) + i] =
            vertex(f[0] + s * f[3] + t * f[6], f[1] + s * f[4] + t * f[7], f[2] + s * f[5] + t * f[8]);
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a00 = ids[j * (n + 1) + i], a10 = ids[j * (n + 1) + i + 1], a01 = ids[(j + 1) * (n + 1) + i],
                  a11 = ids[(j + 1) * (n + 1) + i + 1];
        a.triangles.insert(a.triangles.end(), {a00, a10, a11, a00, a11, a01});
      }
  }
  for (const auto& p : pts) a.positions.insert(a.positions.end(), {p[0], p[1], p[2]});
  return a;
}

// An open cylinder of radius r and height h around the z axis: `around` x `up` quads, split.
inline Arrays cylinder(int around, int up, double r = 1, double h = 2) {
  Arrays a;
  for (int j = 0; j <= up; ++j)
    for (int i = 0; i < around; ++i) {
      const double phi = 2 * kPi * i / around;
      a.positions.insert(a.positions.end(), {r * std::cos(phi), r * std::sin(phi), h * j / up});
    }
  for (int j = 0; j < up; ++j)
    for (int i = 0; i < around; ++i) {
      const int a00 = j * around + i, a10 = j * around + (i + 1) % around, a01 = (j + 1) * around + i,
                a11 = (j + 1) * around + (i + 1) % around;
      a.triangles.insert(a.triangles.end(), {a00, a10, a11, a00, a11, a01});
    }
  return a;
}

// ---- Shapes where points close in space are far apart on the surface (issue 17) ----------------

// A tube around the centre line c(s), s in [0, 1], of radius r(s): along + 1 rings of `around`
// vertices (a discrete rotation-minimising frame carried along the line), quads split in two; with
// `caps` each end is closed by a fan to a vertex on the line.
template <class Centre, class Radius>
Arrays tube(Centre c, Radius r, int along, int around, bool caps) {
  Arrays a;
  auto at = [&](int i) { return c(double(std::clamp(i, 0, along)) / along); };
  Vec3 tangent = (at(1) - at(0)).normalized();
  Vec3 normal = tangent.cross(std::abs(tangent.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
  for (int i = 0; i <= along; ++i) {
    tangent = (at(i + 1) - at(i - 1)).normalized();
    normal = (normal - tangent * normal.dot(tangent)).normalized();
    const Vec3 binormal = tangent.cross(normal), centre = at(i);
    const double radius = r(double(i) / along);
    for (int k = 0; k < around; ++k) {
      const double phi = 2 * kPi * k / around;
      const Vec3 p = centre + radius * (std::cos(phi) * normal + std::sin(phi) * binormal);
      a.positions.insert(a.positions.end(), {p.x(), p.y(), p.z()});
    }
  }
  for (int i = 0; i < along; ++i)
    for (int k = 0; k < around; ++k) {
      const int v00 = i * around + k, v01 = i * around + (k + 1) % around, v10 = v00 + around, v11 = v01 + around;
      a.triangles.insert(a.triangles.end(), {v00, v01, v11, v00, v11, v10});
    }
  if (caps) {
    const int first = a.vertices(), last = first + 1, end = along * around;
    for (const Vec3& p : {at(0), at(along)}) a.positions.insert(a.positions.end(), {p.x(), p.y(), p.z()});
    for (int k = 0; k < around; ++k) {
      const int k1 = (k + 1) % around;
      a.triangles.insert(a.triangles.end(), {first, k1, k, last, end + k, end + k1});
    }
  }
  return a;
}

// The triangles of tube(..., along, around, caps) made `step_along` and `step_around` times coarser,
// over the tube's own vertices (every step_along-th ring, every step_around-th vertex round it): what
// a decimation that keeps a subset of the vertices gives, for the coarse guide (coarse_guide.h).
// along and around must be multiples of the steps.
inline std::vector<int> thinned_tube(int along, int around, bool caps, int step_along, int step_around) {
  const int rings = along / step_along, round = around / step_around;
  auto v = [&](int i, int k) { return i * step_along * around + (k % round) * step_around; };
  std::vector<int> t;
  for (int i = 0; i < rings; ++i)
    for (int k = 0; k < round; ++k)
      t.insert(t.end(), {v(i, k), v(i, k + 1), v(i + 1, k + 1), v(i, k), v(i + 1, k + 1), v(i + 1, k)});
  if (caps) {
    const int first = (along + 1) * around, last = first + 1;
    for (int k = 0; k < round; ++k)
      t.insert(t.end(), {first, v(0, k + 1), v(0, k), last, v(rings, k), v(rings, k + 1)});
  }
  return t;
}

// A tube wound into `turns` turns of a helix of radius 1 and `pitch` per turn, tube radius
// `radius`, open at both ends (the issue's: 8 turns, 0.12, 0.3, 4000 x 48 quads = 384k triangles).
inline Arrays coil(int along, int around, int turns = 8, double radius = 0.12, double pitch = 0.3) {
  auto centre = [&](double s) {
    const double phi = 2 * kPi * turns * s;
    return Vec3(std::cos(phi), std::sin(phi), pitch * turns * s);
  };
  return tube(
      centre, [&](double) { return radius; }, along, around, false);
}

// A tube along a (2,3) torus knot (the knot's centre circle of radius 2, its loops of radius 1),
// tube radius 0.25, cut open and closed by caps: a tube that winds round itself (its centre line
// 1.7 from itself where the strands cross), of rings much closer along it than its vertices around
// it (at 3000 x 24, faces 0.011 along and 0.065 around; the coil's are about square).
inline Arrays knot_tube(int along, int around) {
  auto centre = [](double s) {
    const double t = 2 * kPi * s, r = std::cos(3 * t) + 2;
    return Vec3(r * std::cos(2 * t), r * std::sin(2 * t), -std::sin(3 * t));
  };
  // (cut just short of closing, so that the caps do not meet)
  return tube([&](double s) { return centre(0.995 * s); }, [](double) { return 0.25; }, along, around, true);
}

// A body with limbs folded against it: one closed tube whose middle is a fat body (radius 0.5,
// length 3) and whose ends narrow into limbs (radius 0.12) that bend through 180 degrees and lie
// along opposite sides of the body, 0.04 from it.
inline Arrays folded_body(int along, int around) {
  const double R = 0.5, r = 0.12, gap = 0.04, L = 3, offset = R + gap + r, bend = kPi * offset / 2, limb = 0.9 * L;
  const double total = 2 * (limb + bend) + L;
  auto centre = [=](double s) {
    double t = s * total;
    if (t < limb) return Vec3(offset, 0, L / 2 - limb + t);
    t -= limb;
    if (t < bend) {
      const double phi = kPi * t / bend;
      return Vec3(offset / 2 * (1 + std::cos(phi)), 0, L / 2 + offset / 2 * std::sin(phi));
    }
    t -= bend;
    if (t < L) return Vec3(0, 0, L / 2 - t);
    t -= L;
    if (t < bend) {
      const double phi = kPi * t / bend;
      return Vec3(-offset / 2 * (1 - std::cos(phi)), 0, -L / 2 - offset / 2 * std::sin(phi));
    }
    return Vec3(-offset, 0, -L / 2 + (t - bend));
  };
  // Limb radius r, body radius R, blended (smoothstep) over 0.6 of length where bends meet the body.
  auto radius = [=](double s) {
    const double t = s * total, a = limb + bend, b = a + L, w = 0.6;
    auto ramp = [](double x) { return x <= 0 ? 0 : x >= 1 ? 1 : x * x * (3 - 2 * x); };
    return r + (R - r) * std::min(ramp((t - a) / w + 0.5), ramp((b - t) / w + 0.5));
  };
  return tube(centre, radius, along, around, true);
}

// The connected components of a built mesh's faces (faces sharing an edge): each face's component,
// numbered in the order of their first faces.
// ---- Meshes with long thin faces and graded ones (not tuned on) ---------------------------------

// A unit sphere of `around` x `rings` quads split in two, its poles fans of `around` triangles, as a
// modeler's UV sphere: faces (2 pi / around) by (pi / rings) at the equator, thinner towards the poles.
inline Arrays uv_sphere(int around, int rings) {
  Arrays a;
  a.positions.insert(a.positions.end(), {0, 0, 1});
  for (int j = 1; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double theta = kPi * j / rings, phi = 2 * kPi * i / around;
      a.positions.insert(a.positions.end(),
                         {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
  a.positions.insert(a.positions.end(), {0, 0, -1});
  const int south = rings * around - around + 1;
  auto at = [&](int j, int i) { return 1 + (j - 1) * around + (i % around); };
  for (int i = 0; i < around; ++i) a.triangles.insert(a.triangles.end(), {0, at(1, i), at(1, i + 1)});
  for (int j = 1; j + 1 < rings; ++j)
    for (int i = 0; i < around; ++i)
      a.triangles.insert(a.triangles.end(),
                         {at(j, i), at(j + 1, i), at(j, i + 1), at(j, i + 1), at(j + 1, i), at(j + 1, i + 1)});
  for (int i = 0; i < around; ++i)
    a.triangles.insert(a.triangles.end(), {south, at(rings - 1, i + 1), at(rings - 1, i)});
  return a;
}

// A disc of `rings` rings of `around` quads (split in two) round a centre fan, the ring radii growing
// geometrically from `inner` to 1 (a graded mesh: faces 1/inner times smaller at the centre than at
// the rim), lifted into a gentle bump z = 0.05 sin(3x) cos(2y).
inline Arrays graded_disc(int rings, int around, double inner = 1e-4) {
  Arrays a;
  auto vertex = [&](double x, double y) {
    a.positions.insert(a.positions.end(), {x, y, 0.05 * std::sin(3 * x) * std::cos(2 * y)});
  };
  vertex(0, 0);
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double r = inner * std::pow(1 / inner, double(j) / (rings - 1)), phi = 2 * kPi * i / around;
      vertex(r * std::cos(phi), r * std::sin(phi));
    }
  auto at = [&](int j, int i) { return 1 + j * around + (i % around); };
  for (int i = 0; i < around; ++i) a.triangles.insert(a.triangles.end(), {0, at(0, i), at(0, i + 1)});
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < around; ++i)
      a.triangles.insert(a.triangles.end(),
                         {at(j, i), at(j + 1, i), at(j, i + 1), at(j, i + 1), at(j + 1, i), at(j + 1, i + 1)});
  return a;
}

inline std::vector<int> face_components(const TriMesh& mesh) {
  std::vector<int> part(mesh.triangles.size(), -1), stack;
  int parts = 0;
  for (int s = 0; s < static_cast<int>(part.size()); ++s) {
    if (part[s] >= 0) continue;
    for (part[s] = parts, stack.assign(1, s); !stack.empty();) {
      const int f = stack.back();
      stack.pop_back();
      for (int g : mesh.adjacency[f])
        if (g >= 0 && part[g] < 0) part[g] = parts, stack.push_back(g);
    }
    ++parts;
  }
  return part;
}

// `specks` single triangles added apart from the mesh, at random places in its bounding box (each
// `size` of the box's diagonal across): a scan's debris, its own components.
inline Arrays with_debris(Arrays a, int specks, unsigned seed, double size = 0.01) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int v = 0; v < a.vertices(); ++v) {
    const Vec3 p(a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]);
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  size *= (hi - lo).norm();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < specks; ++i) {
    const Vec3 at = lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(hi - lo);
    const int first = a.vertices();
    for (const Vec3& p : {at, Vec3(at + Vec3(size, 0, 0)), Vec3(at + Vec3(0, size, 0))})
      a.positions.insert(a.positions.end(), {p.x(), p.y(), p.z()});
    a.triangles.insert(a.triangles.end(), {first, first + 1, first + 2});
  }
  return a;
}

// Every vertex moved along its area-weighted normal by uniform noise in +-amount mean edge lengths
// (a scan-like surface from a smooth one).
inline Arrays noisy(Arrays a, double amount, unsigned seed) {
  std::vector<Vec3> normals(a.vertices(), Vec3::Zero());
  auto p = [&](int v) { return Vec3(a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]); };
  double sum = 0;
  for (int f = 0; f < a.faces(); ++f) {
    const int i = a.triangles[3 * f], j = a.triangles[3 * f + 1], k = a.triangles[3 * f + 2];
    const Vec3 n = (p(j) - p(i)).cross(p(k) - p(i));
    normals[i] += n, normals[j] += n, normals[k] += n;
    sum += (p(j) - p(i)).norm() + (p(k) - p(j)).norm() + (p(i) - p(k)).norm();
  }
  const double h = sum / (3.0 * std::max(1, a.faces()));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount * h, amount * h);
  // Copies of a vertex (a file that splits vertices) move together, by the first copy's normal.
  std::map<std::array<double, 3>, Vec3> moved;
  for (int v = 0; v < a.vertices(); ++v) {
    const std::array<double, 3> key = {a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]};
    auto [it, fresh] = moved.try_emplace(key, Vec3::Zero());
    if (fresh) it->second = u(rng) * (normals[v].norm() > 0 ? normals[v].normalized() : Vec3::Zero());
    for (int d = 0; d < 3; ++d) a.positions[3 * v + d] += it->second[d];
  }
  return a;
}

// The mesh point at 3D position x: the face nearest to x with clamped barycentrics. Faces whose
// normal disagrees with `normal` (when given) are skipped, to pick a side on a cube's edges.
// A point uniform in the barycentric triangle of a face chosen uniformly (not uniform in area).
inline MeshPoint random_point(const TriMesh& mesh, std::mt19937& rng) {
  std::uniform_int_distribution<int> face(0, static_cast<int>(mesh.triangles.size()) - 1);
  std::uniform_real_distribution<double> u(0, 1);
  double a = u(rng), b = u(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  return {face(rng), Vec2(a, b)};
}

inline MeshPoint point_at(const TriMesh& mesh, const Vec3& x, const Vec3& normal = Vec3::Zero()) {
  double best = std::numeric_limits<double>::infinity();
  MeshPoint out;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (normal.norm() > 0 && face_normal(mesh, static_cast<int>(f)).dot(normal) < 0.99) continue;
    const auto& t = mesh.triangles[f];
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    Eigen::Matrix<double, 3, 2> m;
    m << b - a, c - a;
    Eigen::Vector2d uv = (m.transpose() * m).ldlt().solve(m.transpose() * (x - a));
    uv = uv.cwiseMax(0.0);
    if (uv.sum() > 1) uv /= uv.sum();
    const double d = (a + m * uv - x).norm();
    if (d < best) best = d, out = {static_cast<int>(f), uv};
  }
  return out;
}

// The shared test data folder (../shared/data next to the repository).
inline std::string shared_data(const std::string& relative) {
  std::string here = __FILE__;  // <repo>/tests/native/surface/test_meshes.h
  for (int i = 0; i < 4; ++i) here = here.substr(0, here.find_last_of('/'));
  return here + "/../shared/data/" + relative;
}

// Positions and triangles of an OBJ (v/f only, polygons fanned) or binary little-endian PLY.
inline Arrays read_mesh(const std::string& path) {
  Arrays a;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  if (path.size() > 4 && path.substr(path.size() - 4) == ".ply") {
    std::string line;
    int nv = 0, nf = 0;
    while (std::getline(in, line)) {
      if (line.rfind("element vertex", 0) == 0) nv = std::stoi(line.substr(15));
      if (line.rfind("element face", 0) == 0) nf = std::stoi(line.substr(13));
      if (line.rfind("end_header", 0) == 0) break;
    }
    // Assumes float x y z and uchar count + int indices (the shared PLY's layout).
    for (int i = 0; i < nv; ++i) {
      float p[3];
      in.read(reinterpret_cast<char*>(p), sizeof p);
      a.positions.insert(a.positions.end(), {p[0], p[1], p[2]});
    }
    for (int f = 0; f < nf; ++f) {
      unsigned char count;
      in.read(reinterpret_cast<char*>(&count), 1);
      std::vector<int> ids(count);
      in.read(reinterpret_cast<char*>(ids.data()), 4 * count);
      for (int k = 1; k + 1 < count; ++k) a.triangles.insert(a.triangles.end(), {ids[0], ids[k], ids[k + 1]});
    }
    return a;
  }
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2) continue;
    if (line[0] == 'v' && line[1] == ' ') {
      std::istringstream s(line.substr(2));
      double x, y, z;
      s >> x >> y >> z;
      a.positions.insert(a.positions.end(), {x, y, z});
    } else if (line[0] == 'f' && line[1] == ' ') {
      std::istringstream s(line.substr(2));
      std::string token;
      std::vector<int> ids;
      while (s >> token) {
        const int id = std::stoi(token.substr(0, token.find('/')));
        ids.push_back(id < 0 ? a.vertices() + id : id - 1);
      }
      for (size_t k = 1; k + 1 < ids.size(); ++k) a.triangles.insert(a.triangles.end(), {ids[0], ids[k], ids[k + 1]});
    }
  }
  return a;
}

}  // namespace splinekit::surface::testing
