// The stability limit of the explicit methods (TimeIntegrationSettings::stabilityLimit):
// the spectral radius rho of df/dy by power iteration on finite differences of f, and the
// step 0.8 r / rho, r the real stability boundary of the tableau that advances. The
// switching method Auto also uses it to judge whether the explicit method is held by stiffness.
#include "capsula/timeint/TimeIntegrationMethod.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace capsula::timeint {

void StepContext::estimateStabilityStep(IntegrationState& state, const std::vector<double>& slope, double boundary,
                                        const std::string& method)
{
  // Power iteration on J v ~ (f(y + eps v) - f(y)) / eps, f(y) = slope. The membrane's
  // J is a product of a symmetric positive mobility and a symmetric stiffness, so its
  // dominant eigenvalue is real and negative and |J v| converges to rho from below.
  const std::size_t n = state.y.size();
  std::vector<double>& v = state.stabilityVector;
  int iterations = 3;
  if (v.size() != n) { // cold start: a fixed vector with every mode in it
    v.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      v[i] = std::sin(0.7 * static_cast<double>(i) + 0.3);
    }
    iterations = 12;
  }
  double scale = 1.0;
  for (const double yi : state.y) {
    scale = std::max(scale, std::abs(yi));
  }
  probe_.resize(n);
  double rho = 0.0;
  for (int k = 0; k < iterations; ++k) {
    double norm = 0.0, largest = 0.0;
    for (const double vi : v) {
      norm += vi * vi;
      largest = std::max(largest, std::abs(vi));
    }
    norm = std::sqrt(norm);
    // Perturb no coordinate by more than 1e-7 of the state's size: small enough for the
    // linearisation, large enough against round-off in f (1e-16 / 1e-7 ~ 1e-9 relative).
    const double eps = 1e-7 * scale / (largest / norm);
    for (std::size_t i = 0; i < n; ++i) {
      probe_[i] = state.y[i] + eps * v[i] / norm;
    }
    evaluate(state.time, probe_, probeSlope_, state, state.proposedStep, 0, method);
    double growth = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      v[i] = (probeSlope_[i] - slope[i]) / eps;
      growth += v[i] * v[i];
    }
    rho = std::sqrt(growth);
    if (!(rho > 0.0)) { // f does not depend on y (or not finitely): no limit
      v.assign(n, 0.0);
      v[0] = 1.0;
      break;
    }
  }
  state.stabilityStep = rho > 0.0 ? 0.8 * boundary / rho : std::numeric_limits<double>::infinity();
  state.stepsSinceStabilityEstimate = 0;
}

} // namespace capsula::timeint
