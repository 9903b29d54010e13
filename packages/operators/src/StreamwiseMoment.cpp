#include "capsula/operators/StreamwiseMoment.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/operators/SurfaceQuadrature.hpp>

#include <cmath>

namespace capsula::operators {

WallNormalWeight crossSectionFluxWeight(double lowerWall, double height)
{
  // The sheet's mean flow u = g y (H - h) / (mu A H) below it and g h (H - y) / (mu A H) above
  // integrates over 0 < y < H to g h (H - h) / (2 mu A).
  return {[=](double y) { return 0.5 * (y - lowerWall) * (height - (y - lowerWall)); },
          [=](double y) { return 0.5 * height - (y - lowerWall); }, 1.0};
}

WallNormalWeight meanWallShearRateWeight(double lowerWall, double height)
{
  // The sheet's du/dy is g (H - h) / (mu A H) on the lower wall and -g h / (mu A H) on the
  // upper one: their mean is g (H - 2 h) / (2 mu A H). (Plain du/dy, the Couette flow's
  // shear rate on both walls, not the shear rate seen from the fluid.)
  return {[=](double y) { return 0.5 - (y - lowerWall) / height; }, [=](double) { return -1.0 / height; }, 0.0};
}

double streamwiseMoment(const CellSurfaces& surfaces, const LoadDensity& load, const double* nodeVelocities,
                        double capillaryNumber, const WallNormalWeight& weight, int quadraturePoints)
{
  core::require(nodeVelocities != nullptr || surfaces.allViscosityRatiosOne(),
                "streamwiseMoment: the node velocities are needed where a viscosity ratio is not 1.");
  SurfaceQuadrature quadrature(quadraturePoints);
  quadrature.update(surfaces);
  const QuadraturePoints& p = quadrature.points();
  const int nq = quadrature.pointsPerElement();
  // The reference point of each cell's interior term: its node mean (any point gives the same
  // term where the velocity has no net flux through the surface).
  std::vector<mesh::Vec3> centres(static_cast<std::size_t>(surfaces.numCells()), mesh::Vec3::Zero());
  for (int c = 0; c < surfaces.numCells(); ++c) {
    const mesh::SurfaceMesh& cell = surfaces.cell(c);
    for (int a = 0; a < cell.numNodes(); ++a) {
      centres[static_cast<std::size_t>(c)] += cell.position(a) / cell.numNodes();
    }
  }
  double loadMoment = 0.0, doubleLayerMoment = 0.0;
  for (int m = 0; m < quadrature.numElements(); ++m) {
    const double* f = load.element(m);
    const std::array<int, 6>& nodes = quadrature.elements().nodes[static_cast<std::size_t>(m)];
    const int cell = surfaces.cellOfElement(m);
    const double doubleLayerFactor = 1.0 - surfaces.viscosityRatio(cell);
    const mesh::Vec3& centre = centres[static_cast<std::size_t>(cell)];
    for (int k = 0; k < nq; ++k) {
      const std::size_t q = static_cast<std::size_t>(m) * nq + k;
      const double* phi = &p.phi[6 * q];
      double fx = 0.0;
      for (int a = 0; a < 6; ++a) {
        fx += phi[a] * f[3 * a];
      }
      loadMoment += fx * weight.value(p.y[q]) * p.weight[q];
      if (doubleLayerFactor != 0.0) {
        double u[3] = {0.0, 0.0, 0.0};
        for (int a = 0; a < 6; ++a) {
          for (int i = 0; i < 3; ++i) {
            u[i] += phi[a] * nodeVelocities[3 * static_cast<std::size_t>(nodes[a]) + i];
          }
        }
        // p.nx, p.ny, p.nz hold n w_k h_s.
        const double outflow = u[0] * p.nx[q] + u[1] * p.ny[q] + u[2] * p.nz[q];
        doubleLayerMoment += doubleLayerFactor * ((u[0] * p.ny[q] + u[1] * p.nx[q]) * weight.slope(p.y[q]) +
                                                  weight.interior * (p.x[q] - centre[0]) * outflow);
      }
    }
  }
  return -loadMoment / capillaryNumber + doubleLayerMoment;
}

} // namespace capsula::operators
