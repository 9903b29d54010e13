#include "capsula/timeint/ButcherTableau.hpp"

#include <cmath>
#include <vector>

#include <algorithm>
#include <utility>

namespace capsula::timeint {

int ButcherTableau::errorEstimateOrder() const
{
  return std::min(order, embeddedOrder) + 1;
}

ButcherTableau rungeKuttaFehlberg45()
{
  ButcherTableau t;
  t.name = "RKF45";
  t.stages = 6;
  // Eq 3.47: rows are the stages k_1..k_6.
  t.a = {
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      1.0 / 4,
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      3.0 / 32,
      9.0 / 32,
      0.0,
      0.0,
      0.0,
      0.0,
      1932.0 / 2197,
      -7200.0 / 2197,
      7296.0 / 2197,
      0.0,
      0.0,
      0.0,
      439.0 / 216,
      -8.0,
      3680.0 / 513,
      -845.0 / 4104,
      0.0,
      0.0,
      -8.0 / 27,
      2.0,
      -3544.0 / 2565,
      1859.0 / 4104,
      -11.0 / 40,
      0.0,
  };
  t.c = {0.0, 1.0 / 4, 3.0 / 8, 12.0 / 13, 1.0, 1.0 / 2};
  // Eq 3.48, ERRATA: 2197/4104 (printed 2197/4101, whose weights do not sum to 1).
  t.b = {25.0 / 216, 0.0, 1408.0 / 2565, 2197.0 / 4104, -1.0 / 5, 0.0};
  // Eq 3.49.
  t.bEmbedded = {16.0 / 135, 0.0, 6656.0 / 12825, 28561.0 / 56430, -9.0 / 50, 2.0 / 55};
  t.order = 4;
  t.embeddedOrder = 5;
  return t;
}

ButcherTableau rungeKuttaFehlberg45Extrapolated()
{
  ButcherTableau t = rungeKuttaFehlberg45();
  t.name = "RKF45 (local extrapolation)";
  std::swap(t.b, t.bEmbedded);
  std::swap(t.order, t.embeddedOrder);
  return t;
}

ButcherTableau dormandPrince45()
{
  ButcherTableau t;
  t.name = "DormandPrince45";
  t.stages = 7;
  t.a = {
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      1.0 / 5,
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      3.0 / 40,
      9.0 / 40,
      0.0,
      0.0,
      0.0,
      0.0,
      0.0,
      44.0 / 45,
      -56.0 / 15,
      32.0 / 9,
      0.0,
      0.0,
      0.0,
      0.0,
      19372.0 / 6561,
      -25360.0 / 2187,
      64448.0 / 6561,
      -212.0 / 729,
      0.0,
      0.0,
      0.0,
      9017.0 / 3168,
      -355.0 / 33,
      46732.0 / 5247,
      49.0 / 176,
      -5103.0 / 18656,
      0.0,
      0.0,
      35.0 / 384,
      0.0,
      500.0 / 1113,
      125.0 / 192,
      -2187.0 / 6784,
      11.0 / 84,
      0.0,
  };
  t.c = {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
  t.b = {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0.0};
  t.bEmbedded = {5179.0 / 57600, 0.0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40};
  t.order = 5;
  t.embeddedOrder = 4;
  t.firstSameAsLast = true;
  return t;
}

ButcherTableau classicalRungeKutta4()
{
  ButcherTableau t;
  t.name = "RK4";
  t.stages = 4;
  t.a = {
      0.0, 0.0, 0.0, 0.0, 1.0 / 2, 0.0, 0.0, 0.0, 0.0, 1.0 / 2, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
  };
  t.c = {0.0, 1.0 / 2, 1.0 / 2, 1.0};
  t.b = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  t.order = 4;
  return t;
}

double stabilityFunction(const ButcherTableau& tableau, double z)
{
  // Explicit: the stage values g_i = 1 + z sum_{j<i} a_ij g_j by forward substitution.
  std::vector<double> g(static_cast<std::size_t>(tableau.stages), 1.0);
  double r = 1.0;
  for (int i = 0; i < tableau.stages; ++i) {
    double sum = 0.0;
    for (int j = 0; j < i; ++j) {
      sum += tableau.coefficient(i, j) * g[static_cast<std::size_t>(j)];
    }
    g[static_cast<std::size_t>(i)] = 1.0 + z * sum;
    r += z * tableau.b[static_cast<std::size_t>(i)] * g[static_cast<std::size_t>(i)];
  }
  return r;
}

double realStabilityBoundary(const ButcherTableau& tableau)
{
  // Scan the negative real axis for the first |R| > 1, then bisect (R is a polynomial of
  // degree <= stages, so a 1e-3 scan cannot step over a stable gap of any explicit method
  // used here).
  const auto unstable = [&](double x) { return std::abs(stabilityFunction(tableau, -x)) > 1.0 + 1e-12; };
  double x = 0.0;
  while (!unstable(x + 1e-3)) {
    x += 1e-3;
    if (x > 100.0) {
      return x;
    }
  }
  double lo = x, hi = x + 1e-3;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (unstable(mid) ? hi : lo) = mid;
  }
  return lo;
}

} // namespace capsula::timeint
