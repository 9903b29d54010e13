#pragma once
// The built-in explicit methods, each an ExplicitRungeKuttaMethod with its error control:
//   RKF45            thesis eqs 3.47-3.50; err = max_i |x5_i - x4_i| (the thesis's |x5 - x4|
//                    for the whole state), judged by the ThesisStepController.
//   DormandPrince45  err = scaled RMS norm with sc_i = Tolerance + Relative tolerance |y_i|,
//                    judged by a PI controller (whose memory lives in the state).
//   RK4              no error estimate: fixed steps.
#include "ExplicitRungeKuttaMethod.hpp"

#include "capsula/timeint/MethodRegistry.hpp"

namespace capsula::timeint::detail {

class FehlbergMethod final : public ExplicitRungeKuttaMethod {
public:
  /// `localExtrapolation`: the 5th-order solution advances instead of the thesis's 4th.
  FehlbergMethod(const TimeIntegrationSettings& settings, bool localExtrapolation);

protected:
  double errorNorm(const std::vector<double>& e, const IntegrationState& state,
                   const std::vector<double>& newState) const override;
  StepDecision decide(double h, double errorNorm, const IntegrationState& state, bool afterRejection) const override;

private:
  ThesisStepController controller_;
};

class DormandPrinceMethod final : public ExplicitRungeKuttaMethod {
public:
  DormandPrinceMethod(const TimeIntegrationSettings& settings, double relativeTolerance);

protected:
  double errorNorm(const std::vector<double>& e, const IntegrationState& state,
                   const std::vector<double>& newState) const override;
  StepDecision decide(double h, double errorNorm, const IntegrationState& state, bool afterRejection) const override;
  void remember(IntegrationState& state, double errorNorm) const override;

private:
  double tolerance_;
  double relativeTolerance_;
  PiStepController controller_;
};

class ClassicalRungeKuttaMethod final : public ExplicitRungeKuttaMethod {
public:
  explicit ClassicalRungeKuttaMethod(const TimeIntegrationSettings& settings);
};

} // namespace capsula::timeint::detail
