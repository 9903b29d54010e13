#include "capsula/elasticity/Prestress.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/mesh/Measures.hpp>

#include <cmath>

namespace capsula::elasticity {

std::vector<double> prestressedReference(const mesh::SurfaceMesh& initialShape, double prestress)
{
  core::require<core::InputError>(std::isfinite(prestress) && prestress >= 0.0,
                                  "the membrane prestress alpha = a/a0 - 1 is ", prestress,
                                  "; give alpha >= 0 (e.g. 0.025 for 2.5%, 0 for none)");
  const mesh::Vec3 c = mesh::centroid(initialShape);
  // X = c + (x - c)/(1 + alpha), written as x - alpha/(1 + alpha) (x - c): exact at alpha = 0.
  const double pull = prestress / (1.0 + prestress);
  std::vector<double> reference(initialShape.positions());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    reference[i] -= pull * (reference[i] - c[static_cast<int>(i % 3)]);
  }
  return reference;
}

} // namespace capsula::elasticity
