// The error control of the built-in explicit methods (ExplicitMethods.hpp).
#include "ExplicitMethods.hpp"

#include "capsula/timeint/VectorNorms.hpp"

namespace capsula::timeint::detail {

FehlbergMethod::FehlbergMethod(const TimeIntegrationSettings& settings, bool localExtrapolation)
    : ExplicitRungeKuttaMethod(localExtrapolation ? rungeKuttaFehlberg45Extrapolated() : rungeKuttaFehlberg45(),
                               settings),
      controller_(settings.tolerance)
{}

double FehlbergMethod::errorNorm(const std::vector<double>& e, const IntegrationState&,
                                 const std::vector<double>&) const
{
  return maxNorm(e.data(), e.size()); // eq 3.50's |x5 - x4|
}

StepDecision FehlbergMethod::decide(double h, double errorNorm, const IntegrationState&, bool afterRejection) const
{
  return controller_.decide(h, errorNorm, afterRejection);
}

DormandPrinceMethod::DormandPrinceMethod(const TimeIntegrationSettings& settings, double relativeTolerance)
    : ExplicitRungeKuttaMethod(dormandPrince45(), settings),
      tolerance_(settings.tolerance),
      relativeTolerance_(relativeTolerance),
      controller_(tableau().errorEstimateOrder(), settings.piController)
{}

double DormandPrinceMethod::errorNorm(const std::vector<double>& e, const IntegrationState& state,
                                      const std::vector<double>& newState) const
{
  return scaledRmsNorm(e.data(), state.y.data(), newState.data(), e.size(), tolerance_, relativeTolerance_);
}

StepDecision DormandPrinceMethod::decide(double h, double errorNorm, const IntegrationState& state,
                                         bool afterRejection) const
{
  return controller_.decide(h, errorNorm, state.previousErrorNorm, afterRejection);
}

void DormandPrinceMethod::remember(IntegrationState& state, double errorNorm) const
{
  state.previousErrorNorm = controller_.rememberedError(errorNorm);
}

ClassicalRungeKuttaMethod::ClassicalRungeKuttaMethod(const TimeIntegrationSettings& settings)
    : ExplicitRungeKuttaMethod(classicalRungeKutta4(), settings)
{}

} // namespace capsula::timeint::detail
