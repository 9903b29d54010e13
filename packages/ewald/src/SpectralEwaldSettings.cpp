#include "capsula/ewald/SpectralEwald2P.hpp"

#include "FftwGrids.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace capsula::ewald {

using detail::fastFftSize;

namespace {

constexpr double settingsPi = 3.14159265358979323846;

/// xi such that the ball of radius r_c = sqrt(ln(1/tol) + 2) / xi holds `neighbours` sources
/// of a uniform density over the cell area times the heights' range.
double xiForNeighbours(const PeriodicLayer& layer, double tolerance, double ySpan, int sourceCount, int neighbours)
{
  const double height = std::max(ySpan, 0.1 * std::min(layer.lengthX, layer.lengthZ));
  const double density = sourceCount / (layer.lengthX * layer.lengthZ * height);
  const double rcTimesXi = std::sqrt(std::log(1.0 / tolerance) + 2.0);
  const double volumePerXi3 = 4.0 / 3.0 * settingsPi * rcTimesXi * rcTimesXi * rcTimesXi;
  return std::cbrt(density * volumePerXi3 / neighbours);
}

} // namespace

double yImagePadding(double a, double tolerance)
{
  // The fixed point of d = (ln(1/tol) + ln(1 + a d)) / a.
  double d = std::log(1.0 / tolerance) / a;
  for (int iteration = 0; iteration < 20; ++iteration) {
    d = (std::log(1.0 / tolerance) + std::log(1.0 + a * d)) / a;
  }
  return d;
}

int yPeriodLevels(const SpectralEwaldSettings& s, double a)
{
  const double span = (s.gridY - 1) * s.spacingY;
  return std::max(s.gridY,
                  fastFftSize(static_cast<int>(std::ceil((span + yImagePadding(a, s.tolerance)) / s.spacingY))));
}

SpectralEwaldSettings spectralEwaldSettings(const PeriodicLayer& layer, double tolerance, double yMin, double yMax,
                                            int sourceCount, double xi, int neighbours)
{
  if (!(layer.lengthX > 0.0) || !(layer.lengthZ > 0.0) || !(tolerance > 0.0) || !(tolerance < 1.0) || !(yMax >= yMin) ||
      sourceCount < 1 || neighbours < 1) {
    throw std::invalid_argument("ewald: spectral Ewald needs positive periods, 0 < tolerance < 1, "
                                "yMax >= yMin, sources and neighbours");
  }
  SpectralEwaldSettings s;
  s.xi = xi > 0.0 ? xi : xiForNeighbours(layer, tolerance, yMax - yMin, sourceCount, neighbours);
  const EwaldTruncation truncation = ewaldTruncation(s.xi, tolerance);
  s.realCutoff = truncation.realCutoff;
  const double logInverse = std::log(1.0 / tolerance);
  s.supportPoints = static_cast<int>(std::ceil(2.0 * logInverse / settingsPi)) + 4;
  const double m = 0.95 * std::sqrt(settingsPi * s.supportPoints);
  const double wavenumberCutoff = 2.0 * s.xi * std::sqrt(logInverse + 6.0);
  // h <= pi / k_c, and small enough that eta = (P h xi / m)^2 stays below 0.9 (the kernel
  // keeps a factor e^{-(1 - eta) k^2 / (4 xi^2)}).
  const double h = std::min(settingsPi / wavenumberCutoff, std::sqrt(0.9) * m / (s.supportPoints * s.xi));
  s.gridX = fastFftSize(static_cast<int>(std::ceil(layer.lengthX / h)));
  s.gridZ = fastFftSize(static_cast<int>(std::ceil(layer.lengthZ / h)));
  s.spacingX = layer.lengthX / s.gridX;
  s.spacingZ = layer.lengthZ / s.gridZ;
  s.spacingY = h;
  s.supportRadius = 0.5 * s.supportPoints * h;
  s.eta = std::pow(2.0 * s.supportRadius * s.xi / m, 2);
  s.gaussianExponent = 2.0 * s.xi * s.xi / s.eta;
  // The y-levels: the spread data [yMin - w, yMax + w] and a level beyond each end; each mode
  // pads its own y-period (yPeriodLevels).
  const double span = yMax - yMin + 2.0 * s.supportRadius + 2.0 * h;
  s.gridY = static_cast<int>(std::ceil(span / h)) + 1;
  s.yOrigin = yMin - s.supportRadius - h;
  s.tolerance = tolerance;
  return s;
}

} // namespace capsula::ewald
