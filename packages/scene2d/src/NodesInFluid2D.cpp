#include "capsula/scene2d/NodesInFluid2D.hpp"

#include <sstream>

namespace capsula::scene2d {

namespace {

std::string describeNode(int node, double x, double y)
{
  std::ostringstream out;
  out << "node " << node << " at (" << x << ", " << y << ") is on or below the wall y = 0";
  return out.str();
}

} // namespace

NodeOutsideFluid::NodeOutsideFluid(int node, double x, double y)
    : timeint::StateOutsideDomain(describeNode(node, x, y)), node_(node), x_(x), y_(y)
{}

int firstNodeOutsideFluid(const std::vector<double>& state)
{
  for (std::size_t i = 1; i < state.size(); i += 2) {
    if (!(state[i] > 0.0)) { // NaN counts as outside as well
      return static_cast<int>(i / 2);
    }
  }
  return -1;
}

void requireNodesInFluid(const std::vector<double>& state)
{
  const int node = firstNodeOutsideFluid(state);
  if (node >= 0) {
    const auto i = static_cast<std::size_t>(node);
    throw NodeOutsideFluid(node, state[2 * i], state[2 * i + 1]);
  }
}

} // namespace capsula::scene2d
