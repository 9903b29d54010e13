#pragma once
// The 2D contour's domain check: every node strictly inside the fluid of the model's
// domain::Domain (above the wall y = 0 with Wall/Enabled).
//
// The plane-wall kernel is defined in the fluid only (a node on or below the wall meets its
// own image). An explicit Runge-Kutta step evaluates the velocity at stage states
// y_n + h sum a_ij k_j that the error control has not judged yet: with a step too large
// for a fast mode, a stage can put a node through the wall although the exact solution
// (and the state a smaller step would reach) stays above it. Right after tethering an
// a/b = 0.25 cell at the sharp end of its contour, the relaxation of the tether node's
// stretch is such a mode: with the preparation's step (k dt = 2e-3 .. 2.5e-2) the first
// stages put node 1 through the wall at 64 and 128 points (docs/tether2d-results.md, a/b = 0.25).
// requireNodesInFluid is the tether run's domain check (TimeIntegrator::setDomainCheck):
// such an attempt is then a rejected step, retried with half the step, and the run fails
// only when the step collapses below the minimum.
#include <capsula/domain/Domain.hpp>

#include <vector>

namespace capsula::scene2d {

/// Throws timeint::StateOutsideDomain naming the first node of the state (x0, y0, x1, y1,
/// ...) on or through a wall of `domain`, or at a height that is not a number.
void requireNodesInFluid(const domain::Domain& domain, const std::vector<double>& state);

} // namespace capsula::scene2d
