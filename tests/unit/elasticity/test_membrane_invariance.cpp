// Frame indifference of the nodal tensions and element loads, tangency of T, and the
// compression (buckling) report.
#include "MembraneTesting.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/elasticity/NeoHookeanLaw.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>
#include <capsula/mesh/Measures.hpp>
#include <capsula/mesh/NodeNormals.hpp>
#include <capsula/mesh/Placement.hpp>
#include <capsula/mesh/Shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace {

using namespace capsula::elasticity;
using capsula::elasticity::testing::mapNodes;
using capsula::elasticity::testing::smoothDeformation;
using capsula::mesh::SurfaceMesh;

const std::vector<std::shared_ptr<const MembraneLaw>> laws = {std::make_shared<NeoHookeanLaw>(1.0),
                                                              std::make_shared<SkalakLaw>(1.0, 10.0)};

} // namespace

TEST(MembraneInvariance, RigidMotionOfTheCurrentShapeRotatesTensionsAndLoads)
{
  const SurfaceMesh mesh = capsula::mesh::makeBiconcaveCell(2);
  const auto current = mapNodes(mesh.positions(), smoothDeformation);
  const Mat3 Q = capsula::mesh::rotationAboutAxis(Vec3(1.0, -2.0, 0.5), 2.3);
  const Vec3 shift(4.0, -1.0, 2.5);
  const auto moved = mapNodes(current, [&](const Vec3& x) { return Vec3(shift + Q * x); });
  for (const auto& law : laws) {
    MembraneMechanics a(mesh, mesh.positions(), law), b(mesh, mesh.positions(), law);
    a.evaluate(current.data());
    b.evaluate(moved.data());
    double tensionScale = 0.0, loadScale = 0.0;
    for (int i = 0; i < mesh.numNodes(); ++i) {
      tensionScale = std::max(tensionScale, a.nodalTensions()[i].norm());
    }
    for (int e = 0; e < mesh.numElements(); ++e) {
      loadScale = std::max(loadScale, a.elementLoads()[e].norm());
    }
    // Every step is rotation-covariant; only round-off of O(1) geometry (coordinates
    // up to ~5 after the shift) remains: 1e-10 of the largest tension or load.
    double tensionChange = 0.0, loadChange = 0.0;
    for (int i = 0; i < mesh.numNodes(); ++i) {
      tensionChange =
          std::max(tensionChange, std::abs(a.nodalPrincipalTensions()[i].minor - b.nodalPrincipalTensions()[i].minor));
      EXPECT_NEAR(a.nodalPrincipalTensions()[i].major, b.nodalPrincipalTensions()[i].major, 1e-10 * tensionScale);
      EXPECT_NEAR(a.nodalPrincipalTensions()[i].minor, b.nodalPrincipalTensions()[i].minor, 1e-10 * tensionScale);
      EXPECT_LT((Q * a.nodalTensions()[i] * Q.transpose() - b.nodalTensions()[i]).norm(), 1e-10 * tensionScale);
    }
    for (int e = 0; e < mesh.numElements(); ++e) {
      loadChange = std::max(loadChange, std::abs(a.elementLoads()[e].norm() - b.elementLoads()[e].norm()));
      EXPECT_NEAR(a.elementLoads()[e].norm(), b.elementLoads()[e].norm(), 1e-10 * loadScale);
      EXPECT_LT((Q * a.elementLoads()[e] - b.elementLoads()[e]).norm(), 1e-10 * loadScale);
    }
    std::printf("  %s: largest change of a principal tension %.1e, of a load magnitude %.1e "
                "(relative to the largest)\n",
                law->name().c_str(), tensionChange / tensionScale, loadChange / loadScale);
    EXPECT_NEAR(a.strainEnergy(current.data()), b.strainEnergy(moved.data()), 1e-12 * a.strainEnergy(current.data()));
  }
}

TEST(MembraneInvariance, RigidMotionOfTheReferenceChangesNothing)
{
  // The law sees the reference only through metric quantities.
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const auto current = mapNodes(mesh.positions(), smoothDeformation);
  const Mat3 Q = capsula::mesh::rotationAboutAxis(Vec3(0.2, 0.1, 1.0), -0.9);
  const auto reference = mapNodes(mesh.positions(), [&](const Vec3& X) { return Vec3(Vec3(1, 2, 3) + Q * X); });
  for (const auto& law : laws) {
    MembraneMechanics a(mesh, mesh.positions(), law), b(mesh, reference, law);
    a.evaluate(current.data());
    b.evaluate(current.data());
    for (int i = 0; i < mesh.numNodes(); ++i) {
      // Same round-off argument as above, on O(1) tensions (G = 1).
      EXPECT_LT((a.nodalTensions()[i] - b.nodalTensions()[i]).norm(), 1e-10);
    }
    for (int e = 0; e < mesh.numElements(); ++e) {
      EXPECT_LT((a.elementLoads()[e] - b.elementLoads()[e]).norm(), 1e-10);
    }
  }
}

TEST(MembraneInvariance, TensionsAreTangentAndCompressionIsReported)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const auto current = mapNodes(mesh.positions(), smoothDeformation);
  for (const auto& law : laws) {
    MembraneMechanics m(mesh, mesh.positions(), law);
    m.evaluate(current.data());
    double smallest = HUGE_VAL;
    int where = -1;
    for (int i = 0; i < mesh.numNodes(); ++i) {
      const Mat3& T = m.nodalTensions()[i];
      const Vec3& n = m.nodeNormals()[i];
      EXPECT_LT((T * n).norm(), 1e-13 * (1.0 + T.norm())); // eq 3.30: T lives in the plane
      EXPECT_LT((T - T.transpose()).norm(), 1e-13 * (1.0 + T.norm()));
      // Principal values are the in-plane eigenvalues of T.
      const auto& p = m.nodalPrincipalTensions()[i];
      EXPECT_NEAR(p.major + p.minor, T.trace(), 1e-12 * (1.0 + T.norm()));
      if (p.minor < smallest) {
        smallest = p.minor;
        where = i;
      }
    }
    // The 0.85 squeeze along y compresses the membrane somewhere.
    EXPECT_LT(smallest, 0.0) << law->name();
    EXPECT_EQ(m.mostCompressiveTension().node, where);
    EXPECT_EQ(m.mostCompressiveTension().tension, smallest);
  }
}

TEST(MembraneInvariance, GeometryAgreesWithTheMeshPackage)
{
  // Node normals and element areas are the thesis's (and capsula::mesh's) definitions:
  // the same arithmetic, so equal to round-off.
  const SurfaceMesh mesh = capsula::mesh::makeSphere(2, 1.0);
  const auto current = mapNodes(mesh.positions(), smoothDeformation);
  MembraneMechanics m(mesh, mesh.positions(), laws[1]);
  m.evaluate(current.data());
  const auto normals = capsula::mesh::nodeNormals(mesh, current.data(), 7);
  const auto areas = capsula::mesh::elementAreas(mesh, current.data(), 7);
  for (int i = 0; i < mesh.numNodes(); ++i) {
    EXPECT_LT((m.nodeNormals()[i] - normals[i]).norm(), 1e-14);
  }
  for (int e = 0; e < mesh.numElements(); ++e) {
    EXPECT_NEAR(m.elementAreas()[e], areas[e], 1e-15);
  }
}

TEST(MembraneInvariance, RejectsInconsistentInputAndFoldedShapes)
{
  const SurfaceMesh mesh = capsula::mesh::makeSphere(1, 1.0);
  const auto law = laws[0];
  std::vector<double> shortReference(mesh.positions().begin(), mesh.positions().end() - 3);
  EXPECT_THROW(MembraneMechanics(mesh, shortReference, law), capsula::core::InputError);
  EXPECT_THROW(MembraneMechanics(mesh, mesh.positions(), nullptr), capsula::core::InputError);
  EXPECT_THROW(MembraneMechanics(mesh, mesh.positions(), law, {5, 4}), capsula::core::InputError);
  EXPECT_THROW(MembraneMechanics(mesh, mesh.positions(), law, {7, 0}), capsula::core::InputError);
  // Flattened onto z = 0: the elements at the equator collapse to zero area.
  MembraneMechanics m(mesh, mesh.positions(), law);
  const std::vector<double> flat = mapNodes(mesh.positions(), [](const Vec3& x) { return Vec3(x[0], x[1], 0.0); });
  EXPECT_THROW(m.evaluate(flat.data()), capsula::core::NumericalError);
}
