#include <capsula/mesh/Icosphere.hpp>
#include "EdgeKey.hpp"
#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace capsula::mesh {

namespace {

using Triangle = std::array<int, 3>;

/// The 12 vertices (0, +-1, +-phi) and cyclic permutations, projected onto the unit
/// sphere, and the 20 faces: the vertex triples whose sides all have the edge length
/// 2, oriented so that (b - a) x (c - a) points away from the origin.
void makeIcosahedron(std::vector<Vec3>& vertices, std::vector<Triangle>& faces)
{
  const double phi = 0.5 * (1.0 + std::sqrt(5.0));
  vertices.clear();
  for (double s1 : {-1.0, 1.0}) {
    for (double s2 : {-phi, phi}) {
      vertices.emplace_back(0.0, s1, s2);
      vertices.emplace_back(s1, s2, 0.0);
      vertices.emplace_back(s2, 0.0, s1);
    }
  }
  const auto isSide = [&](int a, int b) { return std::abs((vertices[a] - vertices[b]).norm() - 2.0) < 1e-9; };
  faces.clear();
  const int n = static_cast<int>(vertices.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      for (int c = b + 1; c < n; ++c) {
        if (isSide(a, b) && isSide(b, c) && isSide(c, a)) {
          const Vec3& xa = vertices[a];
          const Vec3 normal = (vertices[b] - xa).cross(vertices[c] - xa);
          faces.push_back(normal.dot(xa) > 0.0 ? Triangle{a, b, c} : Triangle{a, c, b});
        }
      }
    }
  }
  for (Vec3& v : vertices) {
    v.normalize();
  }
}

/// Index of the projected midpoint of edge a-b, created on first request.
int midpoint(int a, int b, std::vector<Vec3>& vertices, std::unordered_map<std::uint64_t, int>& cache)
{
  const auto [it, inserted] = cache.try_emplace(detail::edgeKey(a, b), static_cast<int>(vertices.size()));
  if (inserted) {
    const Vec3 m = 0.5 * (vertices[a] + vertices[b]);
    vertices.push_back(m.normalized());
  }
  return it->second;
}

} // namespace

SurfaceMesh makeIcosphere(int level)
{
  core::require<core::InputError>(level >= 0 && level <= 7, "makeIcosphere: mesh level ", level,
                                  " is outside 0..7 (N_E = 20 * 4^level)");
  std::vector<Vec3> vertices;
  std::vector<Triangle> faces;
  makeIcosahedron(vertices, faces);

  // Split every triangle into four; orientation is inherited by the children.
  for (int l = 0; l < level; ++l) {
    std::unordered_map<std::uint64_t, int> cache;
    std::vector<Triangle> children;
    children.reserve(faces.size() * 4);
    for (const Triangle& t : faces) {
      const int ab = midpoint(t[0], t[1], vertices, cache);
      const int bc = midpoint(t[1], t[2], vertices, cache);
      const int ca = midpoint(t[2], t[0], vertices, cache);
      children.push_back({t[0], ab, ca});
      children.push_back({ab, t[1], bc});
      children.push_back({ca, bc, t[2]});
      children.push_back({ab, bc, ca});
    }
    faces.swap(children);
  }

  // Midside nodes: the projected edge midpoints, numbered after all vertices.
  std::unordered_map<std::uint64_t, int> cache;
  std::vector<ElementConnectivity> elements;
  elements.reserve(faces.size());
  for (const Triangle& t : faces) {
    const int m01 = midpoint(t[0], t[1], vertices, cache);
    const int m12 = midpoint(t[1], t[2], vertices, cache);
    const int m20 = midpoint(t[2], t[0], vertices, cache);
    elements.push_back({t[0], t[1], t[2], m01, m12, m20});
  }

  std::vector<double> positions;
  positions.reserve(3 * vertices.size());
  for (const Vec3& v : vertices) {
    positions.insert(positions.end(), {v[0], v[1], v[2]});
  }
  return SurfaceMesh(std::move(positions), std::move(elements));
}

} // namespace capsula::mesh
