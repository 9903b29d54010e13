#pragma once
// Time steps that keep the cell in the fluid above the wall.
//
// The plane-wall kernel is defined for y > 0 only (a node on or below the wall meets its
// own image). An explicit Runge-Kutta step evaluates the velocity at stage states
// y_n + h sum a_ij k_j that the error control has not judged yet: with a step too large
// for a fast mode, a stage can put a node through the wall although the exact solution
// (and the state a smaller step would reach) stays above it. Right after tethering an
// a/b = 0.25 cell at the sharp end of its contour, the relaxation of the tether node's
// stretch is such a mode: with the preparation's step (k dt = 2e-3 .. 2.5e-2) the first stages
// threw node 1 through the wall at 64 and 128 points (docs/tether2d.md, a/b = 0.25). Such
// an attempt is a rejected step, as one with a large error estimate is: it is retried with
// half the step, and the run fails only when the step collapses below the minimum.
#include <capsula/timeint/TimeIntegrator.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace capsula::scene2d {

/// Thrown by requireNodesInFluid: a state (a stage state or a step's result) with a node
/// on or below the wall y = 0. stepInFluid turns it into a rejected step (a std exception,
/// so that one thrown anywhere else still reports itself).
class NodeOutsideFluid : public std::runtime_error {
public:
  NodeOutsideFluid(int node, double x, double y);
  int node() const { return node_; }
  double x() const { return x_; }
  double y() const { return y_; }
  std::string describe() const;

private:
  int node_;
  double x_;
  double y_;
};

/// The first node of the state x0, y0, x1, y1, ... with y <= 0, or -1.
int firstNodeOutsideFluid(const std::vector<double>& state);

/// Throws NodeOutsideFluid for the first node with y <= 0 (call it on the state a
/// right-hand side receives, before the wall kernel sees it).
void requireNodesInFluid(const std::vector<double>& state);

/// One accepted step towards tStop, as TimeIntegrator::step, in which neither a stage state
/// (the integrator's right-hand side calls requireNodesInFluid) nor the result has a node
/// on or below the wall. Such an attempt is rejected (counted in the statistics) and
/// retried with half of the step it tried; below the integrator's minimum step it throws
/// core::NumericalError naming the node and time, with `state` the last accepted one.
timeint::StepReport stepInFluid(timeint::TimeIntegrator& integrator, timeint::IntegrationState& state, double tStop);

} // namespace capsula::scene2d
