// Volumes of a cell between heights (SlabVolumes.hpp): exact for the flat-faceted surface
// (they sum to its volume by an independent formula, whatever the cell's position), and
// converging to a sphere's slab volumes at second order in the element size.
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/suspension/FlatFacets.hpp>
#include <capsula/suspension/SlabVolumes.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

namespace mesh = capsula::mesh;
namespace suspension = capsula::suspension;
using mesh::Vec3;

// The flat-faceted volume as the sum of signed tetrahedra from the origin, p0 . (p1 x p2) / 6:
// another formula than the slab volumes' x n_x flux.
double tetrahedraVolume(const mesh::SurfaceMesh& surface)
{
  double volume = 0.0;
  suspension::forEachFlatFacet(
      surface, surface.positionData(), Vec3::Zero(),
      [&](const Vec3& p0, const Vec3& p1, const Vec3& p2) { volume += p0.dot(p1.cross(p2)) / 6.0; });
  return volume;
}

mesh::SurfaceMesh tiltedRedCell(const Vec3& centre)
{
  mesh::Placement placement;
  placement.centre = centre;
  placement.rotation = mesh::rotationAboutAxis(Vec3(1.0, 0.3, -0.4), 0.7);
  return mesh::makeBiconcaveCell(2, {}, placement);
}

// Summed over slabs that cover the cell, the volumes are the flat-faceted volume to round-off
// (1e-13 of it); below the cell nothing, above it all; and moving the cell along x or z (the
// flux's x weight moves with it) changes nothing beyond round-off.
TEST(SlabVolumes, SumToTheFacetedVolumeWhereverTheCellIs)
{
  const auto cell = tiltedRedCell(Vec3(0.3, 2.0, -0.5));
  const double total = tetrahedraVolume(cell);
  // The facets cut the curved elements' volume by O(h^2): 0.85% at level 2 (measured).
  EXPECT_NEAR(total, mesh::enclosedVolume(cell), 0.015 * total);
  const std::vector<double> heights{0.5, 1.1, 1.7, 1.95, 2.3, 2.9, 3.5};
  const auto volumes = suspension::volumesBetweenHeights(cell, heights);
  double sum = 0.0;
  for (double v : volumes) {
    EXPECT_GE(v, -1e-14);
    sum += v;
  }
  EXPECT_NEAR(sum, total, 1e-13 * total);
  EXPECT_EQ(suspension::volumeBelow(cell, 0.0), 0.0);
  EXPECT_NEAR(suspension::volumeBelow(cell, 10.0), total, 1e-13 * total);
  const auto moved = tiltedRedCell(Vec3(17.3, 2.0, -40.5));
  const auto movedVolumes = suspension::volumesBetweenHeights(moved, heights);
  for (std::size_t k = 0; k < volumes.size(); ++k) {
    EXPECT_NEAR(movedVolumes[k], volumes[k], 1e-12) << "slab " << k;
  }
}

// A sphere of radius 1 centred at y = 1.5: between y1 and y2 it holds
// pi ((y2 - y1) - ((y2 - 1.5)^3 - (y1 - 1.5)^3) / 3). The flat facets cut the sphere's
// volume by O(h^2): the largest slab error falls 3.5-4.5 fold per level (4 for second order).
TEST(SlabVolumes, ConvergeToTheSpheresAtSecondOrder)
{
  const std::vector<double> heights{0.5, 0.9, 1.5, 2.2, 2.5};
  const auto exact = [&](std::size_t k) {
    const double a = heights[k] - 1.5, b = heights[k + 1] - 1.5;
    return M_PI * ((b - a) - (b * b * b - a * a * a) / 3.0);
  };
  std::vector<double> errors;
  for (int level : {2, 3, 4}) {
    mesh::Placement placement;
    placement.centre = Vec3(0.2, 1.5, 0.1);
    const auto volumes = suspension::volumesBetweenHeights(mesh::makeSphere(level, 1.0, placement), heights);
    double largest = 0.0;
    for (std::size_t k = 0; k < volumes.size(); ++k) {
      largest = std::max(largest, std::abs(volumes[k] - exact(k)));
    }
    errors.push_back(largest);
  }
  EXPECT_LT(errors[0], 0.05);
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double ratio = errors[i - 1] / errors[i];
    EXPECT_GT(ratio, 3.5) << "level " << i + 2;
    EXPECT_LT(ratio, 4.5) << "level " << i + 2;
  }
}

} // namespace
