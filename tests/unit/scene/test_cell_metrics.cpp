#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/scene/CellMetrics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

namespace mesh = capsula::mesh;
namespace scene = capsula::scene;

TEST(CellMetrics, SphereHasTheKnownShape)
{
  // Level-3 sphere of radius 1.5 at (1, 2, 3): the discretisation errors of area, volume
  // are ~1e-5 relative (the mesh package's measured 4th order), of the footprint pi r^2
  // ~1e-3 (|n_y| has a kink on the equator, slow convergence as documented there).
  mesh::Placement p;
  p.centre = mesh::Vec3(1.0, 2.0, 3.0);
  const auto cell = mesh::makeSphere(3, 1.5, p);
  const auto shape = scene::measureShape(cell);
  EXPECT_NEAR(shape.volume / (4.0 * M_PI / 3.0 * 3.375), 1.0, 1e-4);
  EXPECT_NEAR(shape.area / (4.0 * M_PI * 2.25), 1.0, 1e-4);
  EXPECT_NEAR(shape.reducedVolume, 1.0, 1e-4);
  EXPECT_NEAR(shape.footprintXZ / (M_PI * 2.25), 1.0, 3e-3);
  EXPECT_LT((shape.centroid - p.centre).norm(), 1e-12); // symmetric mesh: exact
  EXPECT_LT(shape.deformation.D12, 1e-4);
}

TEST(CellMetrics, OblateCellOnTheWallHasTheLargerFootprint)
{
  // An oblate spheroid lying flat (symmetry axis along y): footprint pi a^2 with a = 1.2,
  // reduced volume below 1.
  mesh::Placement p;
  p.rotation = mesh::rotationAboutAxis(mesh::Vec3::UnitX(), M_PI / 2.0);
  const auto cell = mesh::makeSpheroid(3, 1.2, 0.6, p);
  const auto shape = scene::measureShape(cell);
  EXPECT_NEAR(shape.footprintXZ / (M_PI * 1.44), 1.0, 3e-3);
  EXPECT_LT(shape.reducedVolume, 0.95);
}

TEST(CellMetrics, MembraneStressIsTheAreaWeightedMeanOfTheLoadMagnitude)
{
  const auto cell = mesh::makeSphere(2, 1.0);
  std::vector<double> loads(3 * static_cast<std::size_t>(cell.numElements()));
  // Uniform magnitude 2 in varying directions: mean = max = 2 exactly.
  for (int e = 0; e < cell.numElements(); ++e) {
    const double a = 0.1 * e;
    loads[3 * e] = 2.0 * std::cos(a);
    loads[3 * e + 1] = 2.0 * std::sin(a);
  }
  auto stress = scene::membraneStress(cell, loads.data());
  EXPECT_NEAR(stress.mean, 2.0, 1e-14);
  EXPECT_NEAR(stress.maximum, 2.0, 1e-14);
  // One element at 10: the mean rises by its area share times 8.
  const auto areas = mesh::elementAreas(cell);
  double total = 0.0;
  for (double a : areas) {
    total += a;
  }
  loads[0] = 10.0;
  loads[1] = loads[2] = 0.0;
  stress = scene::membraneStress(cell, loads.data());
  EXPECT_NEAR(stress.mean, 2.0 + 8.0 * areas[0] / total, 1e-13);
  EXPECT_EQ(stress.maximum, 10.0);
}

} // namespace
