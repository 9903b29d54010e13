#include <capsula/core/Error.hpp>
#include <capsula/scene/CubicSpline.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using capsula::scene::CubicSpline;

double cubic(double t) { return 0.5 - 1.25 * t + 0.75 * t * t - 0.2 * t * t * t; }
double cubicSlope(double t) { return -1.25 + 1.5 * t - 0.6 * t * t; }

TEST(CubicSpline, ReproducesACubicExactlyOnNonUniformSamples)
{
  // Not-a-knot splines reproduce cubics: values and slopes to round-off (1e-12 leaves
  // room for the condition of the tridiagonal solve on these spacings).
  const std::vector<double> t{0.0, 0.3, 0.45, 1.1, 1.2, 2.0, 2.9};
  std::vector<double> f;
  for (double ti : t) {
    f.push_back(cubic(ti));
  }
  const CubicSpline spline(t, f);
  for (double s = 0.0; s <= 2.9; s += 0.037) {
    EXPECT_NEAR(spline.value(s), cubic(s), 1e-12) << "t = " << s;
    EXPECT_NEAR(spline.derivative(s), cubicSlope(s), 1e-11) << "t = " << s;
  }
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_NEAR(spline.sampleDerivatives()[k], cubicSlope(t[k]), 1e-11);
  }
}

TEST(CubicSpline, FewSamplesGiveTheInterpolatingPolynomial)
{
  const CubicSpline one({1.0}, {3.0});
  EXPECT_EQ(one.value(5.0), 3.0);
  EXPECT_EQ(one.derivative(5.0), 0.0);
  const CubicSpline two({1.0, 3.0}, {2.0, 6.0});
  EXPECT_DOUBLE_EQ(two.derivative(3.0), 2.0);
  EXPECT_DOUBLE_EQ(two.value(2.0), 4.0);
  // Parabola f = t^2 through three uneven samples: slope 2t everywhere.
  const CubicSpline three({0.0, 0.5, 2.0}, {0.0, 0.25, 4.0});
  EXPECT_NEAR(three.derivative(2.0), 4.0, 1e-14);
  EXPECT_NEAR(three.derivative(0.0), 0.0, 1e-14);
  EXPECT_NEAR(three.derivative(1.0), 2.0, 1e-14);
}

TEST(CubicSpline, EndSlopeConvergesAtThirdOrder)
{
  // The slope at the LAST sample is what the metrics use at the newest output time. For
  // a smooth f the not-a-knot end slope error is O(h^3): halving h divides it by ~8.
  std::vector<double> errors;
  for (int n : {8, 16, 32, 64}) {
    std::vector<double> t, f;
    for (int k = 0; k <= n; ++k) {
      t.push_back(2.0 * k / n);
      f.push_back(std::sin(3.0 * t.back()));
    }
    const CubicSpline spline(t, f);
    errors.push_back(std::abs(spline.derivative(2.0) - 3.0 * std::cos(6.0)));
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(errors[k - 1] / errors[k]);
    EXPECT_GT(order, 2.7) << "refinement " << k;   // asymptotically 3
  }
  // Size: h^3 |f''''| = (1/32)^3 * 81 = 2.5e-3 times a constant well below 1.
  EXPECT_LT(errors.back(), 5e-4);
}

TEST(CubicSpline, RejectsBadSamples)
{
  EXPECT_THROW(CubicSpline({0.0, 0.0}, {1.0, 2.0}), capsula::core::InputError);
  EXPECT_THROW(CubicSpline({0.0, 1.0}, {1.0}), capsula::core::InputError);
  EXPECT_THROW(CubicSpline({}, {}), capsula::core::InputError);
  EXPECT_THROW(CubicSpline({0.0, 1.0}, {1.0, NAN}), capsula::core::InputError);
}

} // namespace
