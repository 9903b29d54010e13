#pragma once
// int_S f dS over a whole mesh: the element rule (eq 3.39) summed over elements.
#include <capsula/mesh/ElementGeometry.hpp>
#include <capsula/mesh/SurfaceMesh.hpp>

#include <utility>

namespace capsula::mesh {

/// Sum over elements of integrateOverElement, each element parametrised by its own
/// node spacing (eq 3.17). `positions` (3 per node) may be any configuration of the
/// mesh; f takes a SurfacePoint and returns a double, Vec3, Mat3, ...
template <typename Rule, typename Integrand, typename Value>
Value integrateOverSurface(const SurfaceMesh& mesh, const double* positions, const Rule& rule, Integrand&& f,
                           Value zero)
{
  Value sum = zero;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const ElementNodes x = mesh.elementNodes(e, positions);
    sum += integrateOverElement(x, shapeParameters(x), rule, f, zero);
  }
  return sum;
}

/// The same over the mesh's own positions.
template <typename Rule, typename Integrand, typename Value>
Value integrateOverSurface(const SurfaceMesh& mesh, const Rule& rule, Integrand&& f, Value zero)
{
  return integrateOverSurface(mesh, mesh.positionData(), rule, std::forward<Integrand>(f), zero);
}

} // namespace capsula::mesh
