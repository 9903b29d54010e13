#pragma once
// What a linearly implicit (Rosenbrock-W) step needs of the system dy/dt = f(t, y) besides
// f: an approximation J~ of df/dy, frozen at the step's start, and solves with
// W = I - shift J~ (shift = h gamma). The integrator never knows what J~ is: a scene
// implements it with its flow operator and membrane stiffness (scene::VelocityJacobian),
// a small model with a dense finite-difference Jacobian (DenseLinearisedSystem.hpp).
//
// Stage constraints (timeint::StageConstraint, a linear projection P of the velocities)
// belong to J~: a system with one must approximate P df/dy, so that every stage increment
// stays in the constrained subspace.
#include <string>
#include <vector>

namespace capsula::timeint {

/// How one solve with W went.
struct LinearSolveReport {
  bool converged = false;
  int iterations = 0;       ///< Krylov iterations (0 for a direct solve)
  double residualRms = 0.0; ///< achieved ||r - W x||_2 / sqrt(n)
};

class LinearisedSystem {
public:
  virtual ~LinearisedSystem() = default;

  /// Freezes J~ at (t, y). Called once per step before the first solve of that step, and
  /// again after the state was changed outside the integrator.
  virtual void linearise(double t, const std::vector<double>& y) = 0;

  /// Solves (I - shift J~) x = r to an RMS residual ||r - W x||_2 / sqrt(n) of at most
  /// `residualRms`. `x` arrives sized like r; its content is the initial guess. Reports
  /// non-convergence instead of throwing (the integrator then rejects the step).
  virtual LinearSolveReport solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                                  double residualRms) = 0;

  /// The deck keys that control the solves (named in the message when they fail).
  virtual std::string settingsHint() const = 0;
};

} // namespace capsula::timeint
