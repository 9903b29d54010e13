#pragma once
// An explicit Runge-Kutta method given by its Butcher tableau (ButcherTableau.hpp): the
// stages, the embedded error estimate e = h sum_j (b_j - bEmbedded_j) k_j, the stability
// limit and the step-size logic every explicit method shares. What differs between the
// methods, the norm of e and the controller that judges it, is left to the subclasses
// (ExplicitMethods.cpp: RKF45, DormandPrince45, RK4).
#include "capsula/timeint/ButcherTableau.hpp"
#include "capsula/timeint/TimeIntegrationMethod.hpp"

#include <string>
#include <vector>

namespace capsula::timeint::detail {

class ExplicitRungeKuttaMethod : public TimeIntegrationMethod {
public:
  /// Throws (internal) if an adaptive run is asked of a tableau without an error estimate.
  ExplicitRungeKuttaMethod(ButcherTableau tableau, const TimeIntegrationSettings& settings);

  StepReport step(StepContext& context, IntegrationState& state, double tStop) override;
  std::string activeMethodName(const IntegrationState& state) const override;
  std::string describe(const TimeIntegrationSettings& settings) const override;

  const ButcherTableau& tableau() const { return tableau_; }
  /// Operator applications of one step: the stages, and the power iteration's three
  /// right-hand sides every `stabilityInterval` steps.
  double stepCost(const TimeIntegrationSettings& settings) const;
  /// Evaluates f(state.time, state.y) and estimates the stability limit there.
  void estimateStabilityLimit(StepContext& context, IntegrationState& state);

protected:
  /// The norm of the error estimate e of a step from state.y to newState (accept iff the
  /// controller says so).
  virtual double errorNorm(const std::vector<double>& e, const IntegrationState& state,
                           const std::vector<double>& newState) const;
  /// The controller's verdict on an attempt of size h with that norm.
  virtual StepDecision decide(double h, double errorNorm, const IntegrationState& state, bool afterRejection) const;
  /// What the controller keeps of an accepted step in the state (a PI controller's memory).
  virtual void remember(IntegrationState& state, double errorNorm) const;

private:
  // The stages of one attempt of size h ending at tNew into newState_; throws
  // StateOutsideDomain for a stage state or the result outside the model.
  void computeStages(StepContext& context, IntegrationState& state, double h, double tNew);

  ButcherTableau tableau_;
  double stabilityBoundary_ = 0.0;   // r of the tableau that advances
  std::vector<double> errorWeights_; // b - bEmbedded
  // Work arrays, sized on first use.
  std::vector<std::vector<double>> slopes_; // k_1..k_s
  std::vector<double> stageState_, newState_, errorVector_;
};

} // namespace capsula::timeint::detail
