// The element-averaged load by contour integrals (thesis eq 3.37, ERRATA): the edge
// kernel's sign and geometry, and exact cancellation over a closed membrane.
#include "MembraneTesting.hpp"

#include <capsula/elasticity/EdgeTensionForce.hpp>
#include <capsula/elasticity/MembraneMechanics.hpp>
#include <capsula/elasticity/NeoHookeanLaw.hpp>
#include <capsula/elasticity/SkalakLaw.hpp>
#include <capsula/mesh/Shapes.hpp>
#include <capsula/quadrature/GaussLegendre.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

namespace {

using namespace capsula::elasticity;
using capsula::elasticity::testing::mapNodes;
using capsula::elasticity::testing::smoothDeformation;
using capsula::mesh::SurfaceMesh;
using capsula::testing::orderOverLevels;

/// A curved planar edge in z = 0 with the same tension at its three nodes.
EdgeNodalData planarEdge(const Mat3& tension)
{
  EdgeNodalData edge;
  edge.position = {Vec3(0.0, 0.0, 0.0), Vec3(0.35, 0.12, 0.0), Vec3(1.0, 0.05, 0.0)};
  edge.normal = {Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ()};
  edge.tension = {tension, tension, tension};
  return edge;
}

} // namespace

TEST(MembraneContour, EdgeForceOfAUniformTensionIsExactAndPointsOutward)
{
  // Uniform T in the plane: int T . b dl = T . ((x_end - x_start) x n), whatever the
  // curve, because b dl = x' dt x n. Going along +x with n = +z, the element lies to the
  // left (counter-clockwise seen from outside), so b points to -y: out of it.
  const Mat3 T = Vec3(2.0, 0.5, 0.0).asDiagonal();
  const EdgeNodalData edge = planarEdge(T);
  const double tm = edgeMidParameter(edge.position[0], edge.position[1], edge.position[2]);
  const Vec3 chordCrossN = (edge.position[2] - edge.position[0]).cross(Vec3::UnitZ());
  EXPECT_LT(chordCrossN.y(), 0.0);
  for (int points : {1, 2, 4}) {
    const Vec3 force = edgeTensionForce(edge, tm, capsula::quadrature::gaussLegendre(points, 0.0, 1.0));
    // The integrand x'(t) is linear in t: exact for every rule, round-off only.
    EXPECT_LT((force - T * chordCrossN).norm(), 1e-15 * 10) << points << " points";
  }
  // A tension varying along the edge: T(t) = (1 + t^2) I on a straight edge of length 1
  // (n = z, nodes at 0, 1/2, 1): int (1 + t^2) dt = 4/3, along -y. Quadratic: exact
  // with 2 Gauss points.
  EdgeNodalData straight = planarEdge(Mat3::Identity());
  straight.position = {Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0)};
  const Mat3 P = Vec3(1, 1, 0).asDiagonal();
  straight.tension = {P, 1.25 * P, 2.0 * P};
  const Vec3 force = edgeTensionForce(straight, 0.5, capsula::quadrature::gaussLegendre(2, 0.0, 1.0));
  EXPECT_LT((force - Vec3(0.0, -4.0 / 3.0, 0.0)).norm(), 1e-15 * 10);
}

TEST(MembraneContour, NetForceVanishesToRoundOffOnAnyDeformation)
{
  // Each shared edge is integrated once and given to its two elements with opposite
  // signs, so sum_m A_m <Delta f>_m is a sum of exactly cancelling pairs: what is left is
  // the round-off of adding N_E vectors, below 1e-13 of sum |A_m <Delta f>_m|.
  const std::vector<std::shared_ptr<const MembraneLaw>> laws = {std::make_shared<NeoHookeanLaw>(1.0),
                                                                std::make_shared<SkalakLaw>(1.0, 10.0)};
  const std::vector<SurfaceMesh> references = {capsula::mesh::makeSphere(3, 1.0), capsula::mesh::makeBiconcaveCell(2)};
  for (const SurfaceMesh& mesh : references) {
    const auto current = mapNodes(mesh.positions(), smoothDeformation);
    for (const auto& law : laws) {
      MembraneMechanics m(mesh, mesh.positions(), law);
      m.evaluate(current.data());
      double scale = 0.0;
      for (const Vec3& f : m.elementForces()) {
        scale += f.norm();
      }
      EXPECT_GT(scale, 0.1); // a real load, not a trivial zero
      EXPECT_LT(m.netForce().norm(), 1e-13 * scale) << law->name();
      std::printf("  %s, %d elements: |net force| / sum |A_m <Delta f>_m| = %.2e\n", law->name().c_str(),
                  mesh.numElements(), m.netForce().norm() / scale);
    }
  }
}

TEST(MembraneContour, NetTorqueVanishesToRoundOffOnAnyDeformation)
{
  // The element moments are contour integrals too (-oint x x (T . b) dl), each shared
  // edge given to its two elements with opposite signs: the sum cancels in pairs, about
  // any point, leaving the round-off of N_E additions (< 1e-13 of the moment scale).
  const auto law = std::make_shared<SkalakLaw>(1.0, 10.0);
  for (int level = 1; level <= 3; ++level) {
    const SurfaceMesh mesh = capsula::mesh::makeBiconcaveCell(level);
    const auto current = mapNodes(mesh.positions(), smoothDeformation);
    MembraneMechanics m(mesh, mesh.positions(), law);
    m.evaluate(current.data());
    double scale = 0.0;
    for (const Vec3& moment : m.elementMoments()) {
      scale += moment.norm();
    }
    EXPECT_GT(scale, 0.1); // a real load, not a trivial zero
    const Vec3 about(0.3, -0.2, 0.7);
    EXPECT_LT(m.netTorque().norm(), 1e-13 * scale) << "level " << level;
    EXPECT_LT(m.netTorque(about).norm(), 1e-13 * scale) << "level " << level;
    std::printf("  level %d: |net torque| / scale = %.2e\n", level, m.netTorque().norm() / scale);
  }
}

TEST(MembraneContour, TorqueOfThePiecewiseConstantLoadConverges)
{
  // The contour forms cancel exactly, but the torque of a load held uniform over each
  // element, sum_m c_m x A_m <Delta f>_m, differs from the exact (zero) torque by the
  // first moment of the load inside each element: a discretisation error, not round-off.
  const auto law = std::make_shared<SkalakLaw>(1.0, 10.0);
  std::vector<int> levels;
  std::vector<double> torques;
  std::printf("  level  |net torque| / sum |c_m| |A_m <Delta f>_m|\n");
  for (int level = 1; level <= 4; ++level) {
    const SurfaceMesh mesh = capsula::mesh::makeSphere(level, 1.0);
    const auto current = mapNodes(mesh.positions(), smoothDeformation);
    MembraneMechanics m(mesh, mesh.positions(), law);
    m.evaluate(current.data());
    double scale = 0.0;
    for (int e = 0; e < mesh.numElements(); ++e) {
      scale += m.elementCentroids()[e].norm() * m.elementForces()[e].norm();
    }
    levels.push_back(level);
    torques.push_back(m.loadTorque().norm() / scale);
    std::printf("  %5d  %.3e\n", level, torques.back());
  }
  const double order = orderOverLevels(levels, torques);
  std::printf("  observed order %.2f\n", order);
  // Measured: order 2.0, 3.3e-5 at level 3.
  EXPECT_GT(order, 1.8);
  EXPECT_LT(torques[2], 1e-4);
}
