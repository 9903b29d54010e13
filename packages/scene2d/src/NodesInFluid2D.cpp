#include "capsula/scene2d/NodesInFluid2D.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/timeint/TimeIntegrator.hpp>

namespace capsula::scene2d {

void requireNodesInFluid(const domain::Domain& domain, const std::vector<double>& state)
{
  const int node = domain.firstPointOutsideFluid(state.data(), static_cast<int>(state.size() / 2), 2);
  if (node >= 0) {
    const double* x = state.data() + 2 * static_cast<std::size_t>(node);
    throw timeint::StateOutsideDomain(
        core::message("node ", node, " at (", x[0], ", ", x[1], ") reached ", domain.nearestWallName(x[1])));
  }
}

} // namespace capsula::scene2d
