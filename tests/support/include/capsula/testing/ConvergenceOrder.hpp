#pragma once
// Observed orders of convergence: least-squares slopes through errors under refinement,
// shared by every test that checks an order or a rate.
#include <cmath>
#include <cstddef>
#include <vector>

namespace capsula::testing {

/// The least-squares slope of the line through the points (x_i, y_i).
inline double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y)
{
  const double m = static_cast<double>(x.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/// The least-squares slope of log|y| against log x: the exponent q of y ~ x^q.
inline double logLogSlope(const std::vector<double>& x, const std::vector<double>& y)
{
  std::vector<double> logX, logY;
  for (std::size_t i = 0; i < x.size(); ++i) {
    logX.push_back(std::log(x[i]));
    logY.push_back(std::log(std::abs(y[i])));
  }
  return leastSquaresSlope(logX, logY);
}

/// The order p at which `error` falls as the number of points or elements N grows:
/// error ~ N^-p.
inline double fittedOrder(const std::vector<int>& n, const std::vector<double>& error)
{
  return -logLogSlope(std::vector<double>(n.begin(), n.end()), error);
}

/// The order p of error ~ h^p under uniform refinement, the mesh size h halving from one
/// level to the next: the least-squares slope of -log2|error| against the level.
inline double orderOverLevels(const std::vector<int>& levels, const std::vector<double>& errors)
{
  std::vector<double> logErrors;
  for (const double e : errors) {
    logErrors.push_back(std::log2(std::abs(e)));
  }
  return -leastSquaresSlope(std::vector<double>(levels.begin(), levels.end()), logErrors);
}

} // namespace capsula::testing
