#include "capsula/scene/VolumeConstraint.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/NodeNormals.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <cmath>

namespace capsula::scene {

double normalFlux(const mesh::SurfaceMesh& cell, const double* values, int numQuadraturePoints)
{
  const auto& rule = quadrature::triangleRule(numQuadraturePoints);
  double flux = 0.0;
  double phi[6];
  for (int e = 0; e < cell.numElements(); ++e) {
    const mesh::ElementNodes x = cell.elementNodes(e);
    const mesh::ShapeParameters p = mesh::shapeParameters(x);
    const auto& nodes = cell.element(e);
    for (int q = 0; q < rule.size(); ++q) {
      const mesh::SurfacePoint s = mesh::evaluateSurfacePoint(x, p, rule.xi[q], rule.eta[q]);
      mesh::shapeFunctions(p, rule.xi[q], rule.eta[q], phi);
      mesh::Vec3 v = mesh::Vec3::Zero();
      for (int j = 0; j < 6; ++j) {
        v += phi[j] * mesh::nodeAt(values, nodes[j]);
      }
      flux += rule.weight[q] * s.metric * v.dot(s.normal);
    }
  }
  return flux;
}

VolumeConstraint::VolumeConstraint(std::vector<mesh::SurfaceMesh> cells, std::vector<int> nodeOffsets)
    : cells_(std::move(cells)), nodeOffsets_(std::move(nodeOffsets))
{
  core::require(cells_.size() == nodeOffsets_.size(), "VolumeConstraint: ", cells_.size(), " cells but ",
                nodeOffsets_.size(), " node offsets");
}

void VolumeConstraint::apply(const std::vector<double>& positions, std::vector<double>& velocities)
{
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    mesh::SurfaceMesh& cell = cells_[k];
    const std::size_t first = 3 * static_cast<std::size_t>(nodeOffsets_[k]);
    core::require(first + 3 * static_cast<std::size_t>(cell.numNodes()) <= positions.size(),
                  "VolumeConstraint: the state is too short for cell ", k);
    cell.setPositions(positions.data() + first);
    const std::vector<mesh::Vec3> normals = mesh::nodeNormals(cell);
    normals_.resize(3 * normals.size());
    for (std::size_t i = 0; i < normals.size(); ++i) {
      for (int d = 0; d < 3; ++d) {
        normals_[3 * i + static_cast<std::size_t>(d)] = normals[i][d];
      }
    }
    // int (sum phi_k n_k) . n dS is close to the area (n_k . n ~ 1), never near 0 on an
    // unfolded surface.
    const double outward = normalFlux(cell, normals_.data());
    core::require<core::NumericalError>(std::isfinite(outward) && outward > 0.0,
                                        "VolumeConstraint: the node normals of cell ", k, " carry no outward flux (",
                                        outward, "); its surface is inverted or degenerate");
    const double c = normalFlux(cell, velocities.data() + first) / outward;
    for (std::size_t i = 0; i < 3 * normals.size(); ++i) {
      velocities[first + i] -= c * normals_[i];
    }
  }
}

} // namespace capsula::scene
