#include "capsula/adhesion/BondKinetics.hpp"

#include <algorithm>
#include <cmath>

namespace capsula::adhesion {

namespace {

// exp(700) ~ 1e304: a rate that large makes any step's event certain without overflowing.
double cappedExp(double exponent)
{
  return std::exp(std::min(exponent, 700.0));
}

} // namespace

double bondForceMagnitude(const AdhesionSettings& s, double length)
{
  return s.springConstant * std::abs(length - s.equilibriumLength);
}

double offRate(const AdhesionSettings& s, double length)
{
  const double y = length - s.equilibriumLength;
  if (s.model == BondModel::CatchSlip) {
    return s.offRate * cappedExp((s.springConstant - s.transitionSpringConstant) * y * y / (2.0 * s.thermalEnergy));
  }
  return s.offRate * cappedExp(s.reactiveCompliance * s.springConstant * std::abs(y) / s.thermalEnergy);
}

double onRate(const AdhesionSettings& s, double height, double x, double z)
{
  if (height < 0.0 || height > s.reactionDistance || !s.ligandPatch.contains(x, z)) {
    return 0.0;
  }
  const double y = std::abs(height - s.equilibriumLength);
  const double k0 = s.onRate * s.ligandDensity;
  if (s.model == BondModel::CatchSlip) {
    return k0 * cappedExp(-s.transitionSpringConstant * y * y / (2.0 * s.thermalEnergy));
  }
  return k0 * cappedExp(s.springConstant * y * (s.reactiveCompliance - 0.5 * y) / s.thermalEnergy);
}

double eventProbability(double rate, double dt)
{
  return -std::expm1(-rate * dt);
}

double bindingProbability(double onRate, double offRate, double dt)
{
  const double sum = onRate + offRate;
  if (onRate <= 0.0 || dt <= 0.0) {
    return 0.0;
  }
  return onRate / sum * -std::expm1(-sum * dt);
}

double breakageTime(double rate, double u)
{
  return -std::log1p(-u) / rate;
}

} // namespace capsula::adhesion
