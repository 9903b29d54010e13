#pragma once
// Shear stress on the wall y = 0 (thesis Section 3.11.3, eqs 3.60-3.63).
//
// On a no-slip wall the only velocity gradients are du/dy and dw/dy (eq 3.60), so the
// principal wall shear stress is sigma = sqrt((du/dy)^2 + (dw/dy)^2) (eq 3.63), in units
// of mu k (1 for the undisturbed shear flow). Instead of differencing a grid of flow
// points (eqs 3.60-3.62: second order inside, first order at its edges), each wall point
// gets its own one-sided fourth-order stencil of flow velocities (eq 3.59) straight above:
//   du/dy(0) = (-25 u(0) + 48 u(h) - 36 u(2h) + 16 u(3h) - 3 u(4h)) / (12 h) + O(h^4).
// The velocity is smooth up to the wall away from the cells; the error scales with
// (h / H)^4, H the height of the nearest cell: for a sphere of radius 0.2 at height 1,
// h = 0.02 errs by 4e-6, 2e-4 of the largest disturbance gradient on the wall
// (tests/unit/operators/test_flow.cpp). The points may be any set (a grid, a line,
// single probes).
#include <capsula/operators/BoundaryIntegralSolver.hpp>

#include <vector>

namespace capsula::operators {

struct WallShearStress {
  std::vector<double> dudy;      ///< du/dy at each wall point
  std::vector<double> dwdy;      ///< dw/dy at each wall point
  std::vector<double> magnitude; ///< sqrt(dudy^2 + dwdy^2), eq 3.63
};

/// The wall shear stress at the wall points (x, z) (2 numbers each) for the current
/// geometry, loads and node velocities of `solver`; `step` is h above. Collective.
/// Throws core::InputError unless step > 0.
WallShearStress wallShearStress(BoundaryIntegralSolver& solver, const std::vector<double>& wallPoints, double step,
                                const LoadDensity& load, const double* nodeVelocities, const FlowConditions& flow);

} // namespace capsula::operators
