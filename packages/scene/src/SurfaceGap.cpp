#include "capsula/scene/SurfaceGap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace capsula::scene {

using mesh::Vec3;

namespace {

Vec3 closestPointOnSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) {
    return a;
  }
  const double s = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return a + s * ab;
}

// The four flat pieces of a 6-node element (vertices 0, 1, 2; midside nodes 3 on 0-1,
// 4 on 1-2, 5 on 2-0), as in windingNumber.
constexpr std::array<std::array<int, 3>, 4> kPieces{{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}};

struct FlatTriangle {
  Vec3 a, b, c;
  Vec3 centre;   // of the vertices
  double radius; // largest distance from the centre to a vertex
};

Vec3 nodeAt(const double* x, int node)
{
  return {x[3 * node], x[3 * node + 1], x[3 * node + 2]};
}

std::vector<FlatTriangle> flatTriangles(const mesh::SurfaceMesh& surface, const double* x)
{
  std::vector<FlatTriangle> triangles;
  triangles.reserve(4 * static_cast<std::size_t>(surface.numElements()));
  for (int e = 0; e < surface.numElements(); ++e) {
    const auto& nodes = surface.element(e);
    for (const auto& piece : kPieces) {
      FlatTriangle t;
      t.a = nodeAt(x, nodes[piece[0]]);
      t.b = nodeAt(x, nodes[piece[1]]);
      t.c = nodeAt(x, nodes[piece[2]]);
      t.centre = (t.a + t.b + t.c) / 3.0;
      t.radius = std::max({(t.a - t.centre).norm(), (t.b - t.centre).norm(), (t.c - t.centre).norm()});
      triangles.push_back(t);
    }
  }
  return triangles;
}

// Nodes of `from` against the flat triangles of the other surface; improves `gap` (whose
// points are ordered first = `from` unless `swapped`).
void closestApproach(const mesh::SurfaceMesh& from, const double* x, const std::vector<FlatTriangle>& triangles,
                     bool swapped, SurfaceGap& gap)
{
  Vec3 lower = Vec3::Constant(HUGE_VAL), upper = Vec3::Constant(-HUGE_VAL);
  for (const auto& t : triangles) {
    lower = lower.cwiseMin(t.a).cwiseMin(t.b).cwiseMin(t.c);
    upper = upper.cwiseMax(t.a).cwiseMax(t.b).cwiseMax(t.c);
  }
  for (int i = 0; i < from.numNodes(); ++i) {
    const Vec3 p = nodeAt(x, i);
    // A lower bound of the distance to the other surface: the distance to its box.
    const Vec3 outside = (lower - p).cwiseMax(p - upper).cwiseMax(Vec3::Zero());
    if (outside.norm() >= gap.distance) {
      continue;
    }
    for (const auto& t : triangles) {
      if ((p - t.centre).norm() - t.radius >= gap.distance) {
        continue;
      }
      const Vec3 q = closestPointOnTriangle(p, t.a, t.b, t.c);
      const double d = (p - q).norm();
      if (d < gap.distance) {
        gap.distance = d;
        gap.onFirst = swapped ? q : p;
        gap.onSecond = swapped ? p : q;
      }
    }
  }
}

} // namespace

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  // Which Voronoi region of the triangle (a vertex, an edge or the face) holds p, from
  // the signs of the barycentric-like dot products; the face case projects onto the plane.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) {
    return a;
  }
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    return a + (d1 / (d1 - d3)) * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // Degenerate (collinear) triangle: the nearest of its edges.
    const std::array<Vec3, 3> candidates{closestPointOnSegment(p, a, b), closestPointOnSegment(p, b, c),
                                         closestPointOnSegment(p, c, a)};
    return *std::min_element(candidates.begin(), candidates.end(), [&](const Vec3& u, const Vec3& v) {
      return (p - u).squaredNorm() < (p - v).squaredNorm();
    });
  }
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

SurfaceGap minimumSurfaceGap(const mesh::SurfaceMesh& a, const double* xa, const mesh::SurfaceMesh& b, const double* xb)
{
  SurfaceGap gap;
  gap.distance = HUGE_VAL;
  closestApproach(a, xa, flatTriangles(b, xb), false, gap);
  closestApproach(b, xb, flatTriangles(a, xa), true, gap);
  return gap;
}

SurfaceGap minimumSurfaceGap(const mesh::SurfaceMesh& a, const mesh::SurfaceMesh& b)
{
  return minimumSurfaceGap(a, a.positionData(), b, b.positionData());
}

SurfaceGap minimumSurfaceGap(const mesh::SurfaceMesh& a, const double* xa, const mesh::SurfaceMesh& b, const double* xb,
                             const domain::Domain& domain)
{
  if (!domain.isPeriodic()) {
    return minimumSurfaceGap(a, xa, b, xb);
  }
  const std::size_t count = 3 * static_cast<std::size_t>(b.numNodes());
  std::vector<double> image(count);
  SurfaceGap best;
  best.distance = HUGE_VAL;
  const int nx = domain.isPeriodic(domain::flowAxis) ? 1 : 0;
  const int nz = domain.isPeriodic(domain::vorticityAxis) ? 1 : 0;
  for (int i = -nx; i <= nx; ++i) {
    for (int k = -nz; k <= nz; ++k) {
      const mesh::Vec3 shift(i * domain.period(domain::flowAxis), 0.0, k * domain.period(domain::vorticityAxis));
      for (std::size_t n = 0; n < count; ++n) {
        image[n] = xb[n] + shift[static_cast<int>(n % 3)];
      }
      SurfaceGap gap = minimumSurfaceGap(a, xa, b, image.data());
      if (gap.distance < best.distance) {
        gap.onSecond -= shift;
        best = gap;
      }
    }
  }
  return best;
}

} // namespace capsula::scene
