#include "TwoStageMethod.hpp"

#include "capsula/core/ParameterDeclaration.hpp"

#include <algorithm>
#include <memory>
#include <sstream>
#include <vector>

namespace capsula::timeint::testing {

namespace {

class TwoStageMethod final : public TimeIntegrationMethod {
public:
  explicit TwoStageMethod(double alpha) : alpha_(alpha) {}

  StepReport step(StepContext& context, IntegrationState& state, double tStop) override
  {
    const std::size_t n = state.y.size();
    // Fixed steps (MethodTraits::fixedSteps): land on tStop when the step would pass it.
    const double h = std::min(state.proposedStep, tStop - state.time);
    const double tNew = h == tStop - state.time ? tStop : state.time + h;
    context.evaluate(state.time, state.y, k1_, state, h, 0, "TwoStage");
    stage_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      stage_[i] = state.y[i] + alpha_ * h * k1_[i];
    }
    context.checkDomain(stage_);
    context.evaluate(state.time + alpha_ * h, stage_, k2_, state, h, 1, "TwoStage");
    const double b2 = 1.0 / (2.0 * alpha_);
    newState_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      newState_[i] = state.y[i] + h * ((1.0 - b2) * k1_[i] + b2 * k2_[i]);
    }
    context.checkDomain(newState_);
    StepReport report;
    report.shortened = h < state.proposedStep;
    context.recordAcceptedStep(state, report, h, tNew, 0.0, newState_);
    context.proposeNextStep(state, report, state.proposedStep, state.proposedStep);
    return report;
  }

  std::string activeMethodName(const IntegrationState&) const override { return "TwoStage"; }

  std::string describe(const TimeIntegrationSettings& settings) const override
  {
    std::ostringstream line;
    line << "time integration: TwoStage (alpha = " << alpha_ << "), fixed steps of " << settings.initialStep;
    return line.str();
  }

private:
  double alpha_;
  std::vector<double> k1_, k2_, stage_, newState_;
};

} // namespace

void registerTwoStageMethod(MethodRegistry& registry)
{
  auto keys = Teuchos::rcp(new Teuchos::ParameterList("Time integration"));
  core::declareReal(*keys, "Second stage time", 1.0,
                    "TwoStage: alpha, the time of the second stage as a fraction of the step (1: Heun, 0.5: "
                    "explicit midpoint).",
                    core::greaterThan(0.0), core::atMost(1.0));
  MethodTraits traits;
  traits.fixedSteps = true;
  registry.add("TwoStage", {"an explicit two-stage Runge-Kutta method of order 2 with fixed steps.", keys, traits,
                            [](const TimeIntegrationSettings&, const Teuchos::ParameterList& settings) {
                              return std::make_unique<TwoStageMethod>(settings.get<double>("Second stage time"));
                            }});
}

} // namespace capsula::timeint::testing
