#pragma once
// A Rosenbrock-W method (RosenbrockTableau.hpp) as a time-integration method: one
// accepted step with W = I - h gamma J~, J~ frozen at the step's start by the
// LinearisedSystem; its error scaled by Tolerance + Relative tolerance |y_i| and judged by
// a PI controller for the estimate's order. Registered as ROS34PW2 and ROS2; the switching
// method Auto takes its stiff steps and trial steps with it.
#include "capsula/timeint/RosenbrockTableau.hpp"
#include "capsula/timeint/TimeIntegrationMethod.hpp"

#include <string>
#include <vector>

namespace capsula::timeint::detail {

class RosenbrockMethod : public TimeIntegrationMethod {
public:
  /// `relativeTolerance` and `linearTolerance`: the values of those keys.
  RosenbrockMethod(RosenbrockTableau tableau, double relativeTolerance, double linearTolerance);

  StepReport step(StepContext& context, IntegrationState& state, double tStop) override;
  std::string activeMethodName(const IntegrationState& state) const override;
  std::string describe(const TimeIntegrationSettings& settings) const override;

  /// One accepted step; with trialStep > 0 a single attempt of that size, which on failure
  /// leaves the state as it was and reports a step size of 0.
  StepReport attempt(StepContext& context, IntegrationState& state, double tStop, double trialStep);
  double linearTolerance() const { return linearTolerance_; }

private:
  // The stages of one attempt of size h ending at tNew: the increments u_1..u_s and, if
  // every solve converged, newState_. Returns why a solve did not converge ("" if all
  // did); throws StateOutsideDomain for a stage state or result outside the model.
  std::string solveStages(StepContext& context, IntegrationState& state, double h, double tNew, int& iterations);

  RosenbrockTableau tableau_;
  double relativeTolerance_;
  double linearTolerance_;
  PiStepController controller_;
  std::vector<double> difference_; // m - mEmbedded
  // Work arrays, sized on first use.
  std::vector<double> slope_, stageSlope_, stageState_, stageRhs_, newState_, errorVector_;
  std::vector<std::vector<double>> increments_; // u_1..u_s
};

} // namespace capsula::timeint::detail
