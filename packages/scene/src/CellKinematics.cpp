#include "capsula/scene/CellKinematics.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/ShapeFunctions.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <Eigen/Dense>

namespace capsula::scene {

namespace core = capsula::core;
using mesh::Mat3;
using mesh::Vec3;

Vec3 centroidVelocity(const mesh::SurfaceMesh& cell, const double* nodeVelocities, int numQuadraturePoints)
{
  const auto& rule = quadrature::triangleRule(numQuadraturePoints);
  // Volume and centroid (the same integrals as mesh::enclosedVolume and mesh::centroid,
  // with this rule) and the flux moments, in one pass.
  double volume = 0.0;
  Vec3 squareMoment = Vec3::Zero(); // int x_i^2 n_i dS = 2 V x_c,i
  Vec3 fluxMoment = Vec3::Zero();   // int x (u . n) dS
  double flux = 0.0;                // int u . n dS
  double phi[6];
  for (int e = 0; e < cell.numElements(); ++e) {
    const mesh::ElementNodes x = cell.elementNodes(e);
    const mesh::ShapeParameters p = mesh::shapeParameters(x);
    const auto& nodes = cell.element(e);
    for (int q = 0; q < rule.size(); ++q) {
      const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
      mesh::shapeFunctions(p, rule.xi[q], rule.eta[q], phi);
      Vec3 u = Vec3::Zero();
      for (int j = 0; j < 6; ++j) {
        u += phi[j] * mesh::nodeAt(nodeVelocities, nodes[j]);
      }
      const double w = rule.weight[q] * s.metric;
      const double un = u.dot(s.normal);
      volume += w * s.position.dot(s.normal) / 3.0;
      squareMoment += w * s.position.cwiseProduct(s.position).cwiseProduct(s.normal);
      fluxMoment += (w * un) * s.position;
      flux += w * un;
    }
  }
  core::require<core::NumericalError>(volume > 0.0, "centroidVelocity: the cell's volume is ", volume,
                                      "; its surface is inverted or degenerate.");
  const Vec3 centre = squareMoment / (2.0 * volume);
  return (fluxMoment - flux * centre) / volume;
}

RigidMotion rigidMotionFit(const mesh::SurfaceMesh& cell, const double* nodeVelocities, const Vec3& referencePoint)
{
  // Normal equations of the 6 unknowns (U, Omega): u_i ~ U + Omega x r_i = U - [r_i]x Omega.
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for (int i = 0; i < cell.numNodes(); ++i) {
    const Vec3 r = cell.position(i) - referencePoint;
    Mat3 cross;
    cross << 0.0, -r[2], r[1], r[2], 0.0, -r[0], -r[1], r[0], 0.0; // [r]x v = r x v
    Eigen::Matrix<double, 3, 6> row;
    row << Mat3::Identity(), -cross;
    normal += row.transpose() * row;
    rhs += row.transpose() * mesh::nodeAt(nodeVelocities, i);
  }
  const Eigen::Matrix<double, 6, 1> solution = normal.ldlt().solve(rhs);
  RigidMotion motion;
  motion.translation = solution.head<3>();
  motion.rotation = solution.tail<3>();
  return motion;
}

} // namespace capsula::scene
