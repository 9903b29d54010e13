#pragma once
// Method Auto: RKF45 with the stability limit while the membrane is soft, ROS34PW2 while
// it is stiff (the rules: AutoSwitchingMethod.cpp). Which one is active, and the counts
// its decisions rest on, live in the IntegrationState, so a restart repeats them.
#include "ExplicitMethods.hpp"
#include "RosenbrockMethod.hpp"

#include "capsula/timeint/MethodRegistry.hpp"

namespace capsula::timeint::detail {

class AutoSwitchingMethod final : public TimeIntegrationMethod {
public:
  /// `relativeTolerance`, `linearTolerance`: ROS34PW2's keys; `switchMargin`,
  /// `switchSteps`: 'Auto switch margin' and 'Auto switch steps'.
  AutoSwitchingMethod(const TimeIntegrationSettings& settings, double relativeTolerance, double linearTolerance,
                      double switchMargin, int switchSteps);

  StepReport step(StepContext& context, IntegrationState& state, double tStop) override;
  std::string activeMethodName(const IntegrationState& state) const override;
  std::string describe(const TimeIntegrationSettings& settings) const override;

private:
  // Before a step: hand over to ROS34PW2 after a trial step of it that pays off (true:
  // the trial step was accepted and is `report`), or back to RKF45 from a stiff phase.
  bool tryStiffMethod(StepContext& context, IntegrationState& state, double tStop, StepReport& report);
  void reconsiderExplicitMethod(StepContext& context, IntegrationState& state, StepReport& report);
  // Operator applications of a stiff step, as measured so far.
  static double stiffStepCost(const IntegrationState& state);

  FehlbergMethod explicit_;
  RosenbrockMethod stiff_;
  double switchMargin_;
  int switchSteps_;
};

} // namespace capsula::timeint::detail
