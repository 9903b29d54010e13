#include "capsula/adhesion/PointForces.hpp"

namespace capsula::adhesion {

void spreadPointForce(const mesh::ElementConnectivity& nodes, const double phi[6], const mesh::Vec3& force,
                      double* nodalForces)
{
  for (int k = 0; k < 6; ++k) {
    double* f = nodalForces + 3 * nodes[static_cast<std::size_t>(k)];
    f[0] += phi[k] * force[0];
    f[1] += phi[k] * force[1];
    f[2] += phi[k] * force[2];
  }
}

void spreadPointForce(const mesh::SurfaceMesh& mesh, int element, const mesh::ShapeParameters& parameters, double xi,
                      double eta, const mesh::Vec3& force, double* nodalForces)
{
  double phi[6];
  mesh::shapeFunctions(parameters, xi, eta, phi);
  spreadPointForce(mesh.element(element), phi, force, nodalForces);
}

} // namespace capsula::adhesion
