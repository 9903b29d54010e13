#include "capsula/scene/UnfoldedMembranes.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

namespace capsula::scene {

void requireUnfoldedMembranes(const Scene& scene, const std::vector<double>& positions)
{
  for (int c = 0; c < scene.numCells(); ++c) {
    try {
      scene.membrane(c).requireUnfolded(positions.data() + 3 * static_cast<std::size_t>(scene.nodeOffset(c)));
    } catch (const core::NumericalError& e) {
      throw timeint::StateOutsideDomain(core::message(
          "the membrane of '", scene.description().cells[static_cast<std::size_t>(c)].path, "' failed: ", e.what()));
    }
  }
}

} // namespace capsula::scene
