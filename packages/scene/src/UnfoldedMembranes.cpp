#include "capsula/scene/UnfoldedMembranes.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

namespace capsula::scene {

void requireUnfoldedMembranes(const Scene& scene, const std::vector<double>& positions)
{
  // Each owner checks its cells; every rank rejects the state with the first folded cell.
  scene.cellOwnership().forEachOwnedCell([&](int c) {
    try {
      scene.membrane(c).requireUnfolded(positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c)));
    } catch (const core::NumericalError& e) {
      throw timeint::StateOutsideDomain(core::message(
          "the membrane of '", scene.description().cells[static_cast<std::size_t>(c)].path, "' failed: ", e.what()));
    }
  });
}

} // namespace capsula::scene
