#include "capsula/operators/WallShearStress.hpp"

#include <capsula/core/Error.hpp>

#include <cmath>

namespace capsula::operators {

WallShearStress wallShearStress(BoundaryIntegralSolver& solver, const std::vector<double>& wallPoints, double step,
                                const LoadDensity& load, const double* nodeVelocities, const FlowConditions& flow)
{
  core::require<core::InputError>(step > 0.0 && std::isfinite(step), "The wall shear stress step is ", step,
                                  "; it must be a finite number > 0.");
  core::require<core::InputError>(wallPoints.size() % 2 == 0, "Wall points come as (x, z) pairs; got ",
                                  wallPoints.size(), " numbers.");
  // One-sided fourth-order stencil on heights 0, h, 2h, 3h, 4h: error h^4 u^(5) / 5.
  constexpr int levels = 5;
  constexpr double weights[levels] = {-25.0, 48.0, -36.0, 16.0, -3.0}; // / (12 h)
  const std::size_t n = wallPoints.size() / 2;
  std::vector<double> points;
  points.reserve(3 * levels * n);
  for (std::size_t p = 0; p < n; ++p) {
    for (int level = 0; level < levels; ++level) {
      points.insert(points.end(), {wallPoints[2 * p], level * step, wallPoints[2 * p + 1]});
    }
  }
  const std::vector<double> u = solver.flowVelocity(points, load, nodeVelocities, flow);
  WallShearStress result;
  result.dudy.resize(n);
  result.dwdy.resize(n);
  result.magnitude.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    double dudy = 0.0, dwdy = 0.0;
    for (int level = 0; level < levels; ++level) {
      const std::size_t k = 3 * (levels * p + level);
      dudy += weights[level] * u[k];
      dwdy += weights[level] * u[k + 2];
    }
    result.dudy[p] = dudy / (12.0 * step);
    result.dwdy[p] = dwdy / (12.0 * step);
    result.magnitude[p] = std::hypot(result.dudy[p], result.dwdy[p]);
  }
  return result;
}

} // namespace capsula::operators
