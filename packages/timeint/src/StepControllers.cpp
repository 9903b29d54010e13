#include "capsula/timeint/StepControllers.hpp"

#include "capsula/core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace capsula::timeint {

ThesisStepController::ThesisStepController(double tolerance) : tolerance_(tolerance)
{
  core::require<core::InputError>(tolerance > 0.0 && std::isfinite(tolerance),
                                  "The time-integration tolerance must be a real number > 0, got ", tolerance, ".");
}

double ThesisStepController::stepRatio(double errorEstimate) const
{
  if (errorEstimate <= 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  return std::pow(0.5 * tolerance_ / errorEstimate, 0.25); // eq 3.50
}

StepDecision ThesisStepController::decide(double step, double errorEstimate, bool afterRejection) const
{
  const double s = stepRatio(errorEstimate);
  if (!(s >= 0.75)) { // also rejects a NaN estimate
    return {false, 0.5 * step};
  }
  const bool grow = s > 1.5 && !afterRejection;
  return {true, grow ? 2.0 * step : step};
}

PiStepController::PiStepController(int errorOrder, PiControllerParameters parameters)
    : errorOrder_(errorOrder), parameters_(parameters)
{
  core::require(errorOrder >= 1, "internal: PI controller error order must be >= 1");
  core::require(parameters.minimumFactor > 0.0 && parameters.minimumFactor < 1.0 && parameters.maximumFactor > 1.0 &&
                    parameters.safety > 0.0 && parameters.safety <= 1.0 && parameters.errorFloor > 0.0,
                "internal: inconsistent PI controller parameters");
}

double PiStepController::rememberedError(double errorNorm) const
{
  return std::max(errorNorm, parameters_.errorFloor);
}

StepDecision PiStepController::decide(double step, double errorNorm, double previousErrorNorm,
                                      bool afterRejection) const
{
  const PiControllerParameters& p = parameters_;
  if (!(errorNorm <= 1.0)) {
    const double shrink = p.safety * std::pow(errorNorm, -1.0 / errorOrder_);
    // A NaN or infinite error gives the largest cut.
    const double factor = std::isfinite(shrink) ? std::max(p.minimumFactor, shrink) : p.minimumFactor;
    return {false, step * std::min(factor, 1.0)};
  }
  const double err = std::max(errorNorm, std::numeric_limits<double>::min());
  double factor = p.safety * std::pow(err, -p.alpha) * std::pow(std::max(previousErrorNorm, p.errorFloor), p.beta);
  factor = std::clamp(factor, p.minimumFactor, p.maximumFactor);
  if (afterRejection) {
    factor = std::min(factor, 1.0);
  }
  return {true, step * factor};
}

} // namespace capsula::timeint
