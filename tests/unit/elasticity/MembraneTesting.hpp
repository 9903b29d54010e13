#pragma once
// Small helpers shared by the 3D membrane tests: mapping a configuration node by node,
// a smooth non-affine deformation; the observed order of convergence comes from
// capsula/testing/ConvergenceOrder.hpp.
#include "capsula/testing/ConvergenceOrder.hpp"

#include <capsula/mesh/Vec3.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace capsula::elasticity::testing {

using mesh::Vec3;

/// y_i = map(x_i) for every node of a flat position array.
template <typename Map>
std::vector<double> mapNodes(const std::vector<double>& positions, Map&& map)
{
  std::vector<double> mapped(positions.size());
  for (std::size_t i = 0; i < positions.size(); i += 3) {
    const Vec3 y = map(Vec3(positions[i], positions[i + 1], positions[i + 2]));
    mapped[i] = y[0];
    mapped[i + 1] = y[1];
    mapped[i + 2] = y[2];
  }
  return mapped;
}

/// A smooth, non-affine, orientation-preserving deformation of the unit ball's
/// surface: stretches, shears and bends, with principal stretches between ~0.8 and ~1.3,
/// so both tension and compression occur.
inline Vec3 smoothDeformation(const Vec3& X)
{
  return Vec3(1.25 * X[0] + 0.15 * X[1] * X[2], 0.85 * X[1] + 0.1 * X[0] * X[0],
              X[2] * (1.0 + 0.2 * X[0]) - 0.05 * X[1]);
}

} // namespace capsula::elasticity::testing
