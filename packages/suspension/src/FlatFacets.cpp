#include "capsula/suspension/FlatFacets.hpp"

namespace capsula::suspension {

void forEachFlatFacet(const mesh::SurfaceMesh& surface, const double* positions, const mesh::Vec3& shift,
                      const std::function<void(const mesh::Vec3&, const mesh::Vec3&, const mesh::Vec3&)>& visit)
{
  for (int e = 0; e < surface.numElements(); ++e) {
    const auto& nodes = surface.element(e);
    for (const auto& piece : flatFacetPieces) {
      visit(mesh::nodeAt(positions, nodes[piece[0]]) + shift, mesh::nodeAt(positions, nodes[piece[1]]) + shift,
            mesh::nodeAt(positions, nodes[piece[2]]) + shift);
    }
  }
}

} // namespace capsula::suspension
