// Barycentric Lagrange interpolation at Chebyshev points of the second kind: exact for
// polynomials of the degree, a partition of unity, the unit vector at a node, and
// geometric convergence for a function analytic near the interval.
#include <capsula/fastsum/BarycentricLagrange.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace capsula::fastsum;

TEST(BarycentricLagrange, ReproducesPolynomialsOfItsDegree)
{
  const int n = 7;
  double s[n + 1], L[n + 1];
  chebyshevPoints(n, -0.3, 1.7, s);
  const auto p = [](double x) { return 1.0 - 2.0 * x + 0.5 * std::pow(x, 4) - 0.1 * std::pow(x, 7); };
  for (double x = -0.3; x <= 1.7; x += 0.0173) {
    lagrangeBasis(n, s, x, L);
    double value = 0.0, sum = 0.0;
    for (int k = 0; k <= n; ++k) {
      value += L[k] * p(s[k]);
      sum += L[k];
    }
    // Round-off of a sum of 8 terms of size ~10.
    EXPECT_NEAR(value, p(x), 1e-13);
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
}

TEST(BarycentricLagrange, IsTheUnitVectorAtANode)
{
  const int n = 5;
  double s[n + 1], L[n + 1];
  chebyshevPoints(n, 2.0, 3.0, s);
  EXPECT_EQ(s[0], 3.0);
  EXPECT_EQ(s[n], 2.0);
  for (int k = 0; k <= n; ++k) {
    lagrangeBasis(n, s, s[k], L);
    for (int l = 0; l <= n; ++l) {
      EXPECT_EQ(L[l], l == k ? 1.0 : 0.0);
    }
  }
  // A degenerate interval: every point at the node, all weight on the first.
  chebyshevPoints(n, 1.0, 1.0, s);
  lagrangeBasis(n, s, 1.0, L);
  EXPECT_EQ(L[0], 1.0);
}

TEST(BarycentricLagrange, ConvergesGeometricallyForAFarPole)
{
  // 1 / (x - 3) on [-1, 1]: the pole is at rho = 3 + sqrt(8) ~ 5.8 (Bernstein ellipse), so
  // the error falls like rho^-n (Trefethen, ATAP Thm 8.2); each degree must gain at least a
  // factor 4.
  const auto f = [](double x) { return 1.0 / (x - 3.0); };
  double previous = 1.0;
  for (int n = 2; n <= 12; n += 2) {
    double s[maxInterpolationDegree + 1], L[maxInterpolationDegree + 1];
    chebyshevPoints(n, -1.0, 1.0, s);
    double worst = 0.0;
    for (double x = -1.0; x <= 1.0; x += 0.001) {
      lagrangeBasis(n, s, x, L);
      double value = 0.0;
      for (int k = 0; k <= n; ++k) {
        value += L[k] * f(s[k]);
      }
      worst = std::max(worst, std::abs(value - f(x)));
    }
    EXPECT_LT(worst, previous / 16.0) << "degree " << n;
    previous = worst;
  }
  EXPECT_LT(previous, 1e-9);
}
