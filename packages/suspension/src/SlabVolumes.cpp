#include "capsula/suspension/SlabVolumes.hpp"

#include "capsula/suspension/FlatFacets.hpp"

#include <capsula/core/Error.hpp>

#include <vector>

namespace capsula::suspension {

namespace {

using mesh::Vec3;

// The part of triangle (p0, p1, p2) with y < height, as a polygon (Sutherland-Hodgman against
// one plane): 0, 3 or 4 vertices, in the triangle's orientation.
std::vector<Vec3> partBelow(const Vec3& p0, const Vec3& p1, const Vec3& p2, double height)
{
  const Vec3 corners[3] = {p0, p1, p2};
  std::vector<Vec3> polygon;
  for (int i = 0; i < 3; ++i) {
    const Vec3& a = corners[i];
    const Vec3& b = corners[(i + 1) % 3];
    const bool aBelow = a[1] < height, bBelow = b[1] < height;
    if (aBelow) {
      polygon.push_back(a);
    }
    if (aBelow != bBelow) {
      const double t = (height - a[1]) / (b[1] - a[1]);
      polygon.push_back(a + t * (b - a));
    }
  }
  return polygon;
}

// int_T x n_x dS over the part of the flat triangle below `height`: with A2 = (p1 - p0) x
// (p2 - p0), each fan triangle (q0, q_i, q_i+1) of the part contributes A2_x / 2 times its area
// over the whole triangle's (s2 . A2 / |A2|^2) times the mean x of its corners.
double fluxBelow(const Vec3& p0, const Vec3& p1, const Vec3& p2, double height)
{
  const Vec3 twiceArea = (p1 - p0).cross(p2 - p0);
  const double norm2 = twiceArea.squaredNorm();
  if (norm2 == 0.0) {
    return 0.0;
  }
  const std::vector<Vec3> polygon = partBelow(p0, p1, p2, height);
  double flux = 0.0;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Vec3& q0 = polygon[0];
    const Vec3& q1 = polygon[i];
    const Vec3& q2 = polygon[i + 1];
    const double ratio = (q1 - q0).cross(q2 - q0).dot(twiceArea) / norm2;
    flux += 0.5 * twiceArea[0] * ratio * (q0[0] + q1[0] + q2[0]) / 3.0;
  }
  return flux;
}

} // namespace

double volumeBelow(const mesh::SurfaceMesh& surface, double height)
{
  double volume = 0.0;
  forEachFlatFacet(surface, surface.positionData(), Vec3::Zero(),
                   [&](const Vec3& p0, const Vec3& p1, const Vec3& p2) { volume += fluxBelow(p0, p1, p2, height); });
  return volume;
}

std::vector<double> volumesBetweenHeights(const mesh::SurfaceMesh& surface, const std::vector<double>& heights)
{
  core::require<core::InputError>(heights.size() >= 2, "volumesBetweenHeights: give at least two heights.");
  std::vector<double> volumes;
  double below = volumeBelow(surface, heights[0]);
  for (std::size_t k = 1; k < heights.size(); ++k) {
    core::require<core::InputError>(heights[k] > heights[k - 1], "volumesBetweenHeights: the heights must increase.");
    const double next = volumeBelow(surface, heights[k]);
    volumes.push_back(next - below);
    below = next;
  }
  return volumes;
}

} // namespace capsula::suspension
