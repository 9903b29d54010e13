// Cubic splines and their building blocks: tridiagonal solvers, Gauss-Legendre rule,
// and the spline fits checked against the defining conditions (eqs A.17-A.20, A.31-A.34).
#include <capsula/contour/CubicSpline.hpp>
#include <capsula/contour/Tridiagonal.hpp>
#include <capsula/core/Error.hpp>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace {

using capsula::contour::CubicPiece;
using capsula::contour::CubicSpline;
using capsula::contour::SplineEnds;

std::vector<double> randomKnots(int pieces, std::mt19937& generator)
{
  std::uniform_real_distribution<double> step(0.3, 1.7);
  std::vector<double> knots{-0.4};
  for (int k = 0; k < pieces; ++k) {
    knots.push_back(knots.back() + step(generator));
  }
  return knots;
}

/// The spline from its definition: 4n unknown coefficients, interpolation (A.17),
/// continuity of p, p', p'' at interior knots (A.18-A.20) plus the two end conditions,
/// solved densely. An independent check of the tridiagonal route (A.21-A.25).
std::vector<CubicPiece> splineByDefinition(const std::vector<double>& s, const std::vector<double>& y, SplineEnds ends,
                                           double startSlope = 0.0, double endSlope = 0.0)
{
  const int n = static_cast<int>(s.size()) - 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4 * n, 4 * n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(4 * n);
  int row = 0;
  // Unknown layout per piece: (a, b, c, d).
  auto valueRow = [&](int k, double ds) {
    a(row, 4 * k) = ds * ds * ds;
    a(row, 4 * k + 1) = ds * ds;
    a(row, 4 * k + 2) = ds;
    a(row, 4 * k + 3) = 1.0;
  };
  auto slopeRow = [&](int k, double ds, double sign) {
    a(row, 4 * k) += sign * 3.0 * ds * ds;
    a(row, 4 * k + 1) += sign * 2.0 * ds;
    a(row, 4 * k + 2) += sign;
  };
  auto curvatureRow = [&](int k, double ds, double sign) {
    a(row, 4 * k) += sign * 6.0 * ds;
    a(row, 4 * k + 1) += sign * 2.0;
  };
  auto third = [&](int k, double sign) { a(row, 4 * k) += sign * 6.0; };
  for (int k = 0; k < n; ++k) {
    const double h = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
    valueRow(k, 0.0);
    rhs(row++) = y[static_cast<std::size_t>(k)];
    valueRow(k, h);
    rhs(row++) = ends == SplineEnds::Periodic && k == n - 1 ? y[0] : y[static_cast<std::size_t>(k) + 1];
  }
  const int joints = ends == SplineEnds::Periodic ? n : n - 1;
  for (int k = 0; k < joints; ++k) {
    const double h = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
    const int next = (k + 1) % n;
    slopeRow(k, h, 1.0);
    slopeRow(next, 0.0, -1.0);
    ++row;
    curvatureRow(k, h, 1.0);
    curvatureRow(next, 0.0, -1.0);
    ++row;
  }
  const double hLast = s.back() - s[s.size() - 2];
  if (ends == SplineEnds::Natural) {
    curvatureRow(0, 0.0, 1.0);
    ++row;
    curvatureRow(n - 1, hLast, 1.0);
    ++row;
  } else if (ends == SplineEnds::Clamped) {
    slopeRow(0, 0.0, 1.0);
    rhs(row++) = startSlope;
    slopeRow(n - 1, hLast, 1.0);
    rhs(row++) = endSlope;
  } else if (ends == SplineEnds::NotAKnot) {
    third(0, 1.0);
    third(1, -1.0);
    ++row;
    third(n - 2, 1.0);
    third(n - 1, -1.0);
    ++row;
  }
  EXPECT_EQ(row, 4 * n);
  const Eigen::VectorXd x = a.fullPivLu().solve(rhs);
  std::vector<CubicPiece> pieces(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    pieces[static_cast<std::size_t>(k)] = {x(4 * k), x(4 * k + 1), x(4 * k + 2), x(4 * k + 3)};
  }
  return pieces;
}

void expectSamePieces(const CubicSpline& spline, const std::vector<CubicPiece>& expected)
{
  ASSERT_EQ(spline.numberOfPieces(), static_cast<int>(expected.size()));
  for (int k = 0; k < spline.numberOfPieces(); ++k) {
    const CubicPiece& p = spline.piece(k);
    const CubicPiece& q = expected[static_cast<std::size_t>(k)];
    // O(1) data and spacings, condition number of the dense system ~1e3: 1e-11 is
    // round-off with margin.
    EXPECT_NEAR(p.a, q.a, 1e-11) << "piece " << k;
    EXPECT_NEAR(p.b, q.b, 1e-11) << "piece " << k;
    EXPECT_NEAR(p.c, q.c, 1e-11) << "piece " << k;
    EXPECT_NEAR(p.d, q.d, 1e-11) << "piece " << k;
  }
}

TEST(ContourTridiagonal, ThomasMatchesDenseSolve)
{
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 9;
  std::vector<double> lower(n), diagonal(n), upper(n), rhs(n);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    lower[k] = u(generator);
    upper[k] = u(generator);
    diagonal[k] = 3.0 + u(generator);
    rhs[k] = b(i) = u(generator);
    a(i, i) = diagonal[k];
    if (i > 0) {
      a(i, i - 1) = lower[k];
    }
    if (i + 1 < n) {
      a(i, i + 1) = upper[k];
    }
  }
  capsula::contour::solveTridiagonal(lower, diagonal, upper, rhs);
  const Eigen::VectorXd x = a.partialPivLu().solve(b);
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(rhs[static_cast<std::size_t>(i)], x(i), 1e-14); // well-conditioned, O(1)
  }
}

TEST(ContourTridiagonal, CyclicShermanMorrisonMatchesDenseSolve)
{
  std::mt19937 generator(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {3, 4, 10}) {
    std::vector<double> lower(static_cast<std::size_t>(n)), diagonal(lower), upper(lower), rhs(lower);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      lower[k] = u(generator);
      upper[k] = u(generator);
      diagonal[k] = 3.0 + u(generator);
      rhs[k] = b(i) = u(generator);
      a(i, i) = diagonal[k];
      a(i, (i + n - 1) % n) += lower[k];
      a(i, (i + 1) % n) += upper[k];
    }
    capsula::contour::solveCyclicTridiagonal(lower, diagonal, upper, rhs);
    const Eigen::VectorXd x = a.partialPivLu().solve(b);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(rhs[static_cast<std::size_t>(i)], x(i), 1e-14) << "n = " << n;
    }
  }
}

TEST(ContourSpline, FitsMatchTheDefiningConditions)
{
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const std::vector<double> knots = randomKnots(7, generator);
  std::vector<double> values;
  for (std::size_t k = 0; k < knots.size(); ++k) {
    values.push_back(u(generator));
  }
  const std::vector<double> periodicValues(values.begin(), values.end() - 1);

  expectSamePieces(CubicSpline::natural(knots, values), splineByDefinition(knots, values, SplineEnds::Natural));
  expectSamePieces(CubicSpline::clamped(knots, values, 0.7, -1.3),
                   splineByDefinition(knots, values, SplineEnds::Clamped, 0.7, -1.3));
  expectSamePieces(CubicSpline::notAKnot(knots, values), splineByDefinition(knots, values, SplineEnds::NotAKnot));
  expectSamePieces(CubicSpline::periodic(knots, periodicValues),
                   splineByDefinition(knots, values, SplineEnds::Periodic));
}

TEST(ContourSpline, ClampedAndNotAKnotAreExactForCubics)
{
  std::mt19937 generator(5);
  const std::vector<double> knots = randomKnots(6, generator);
  auto p = [](double s) { return 0.3 * s * s * s - 1.1 * s * s + 0.4 * s + 2.0; };
  auto dp = [](double s) { return 0.9 * s * s - 2.2 * s + 0.4; };
  auto ddp = [](double s) { return 1.8 * s - 2.2; };
  std::vector<double> values;
  for (double s : knots) {
    values.push_back(p(s));
  }
  const CubicSpline clamped = CubicSpline::clamped(knots, values, dp(knots.front()), dp(knots.back()));
  const CubicSpline notAKnot = CubicSpline::notAKnot(knots, values);
  for (const CubicSpline* spline : {&clamped, &notAKnot}) {
    for (int i = 0; i <= 50; ++i) {
      const double s = knots.front() + (knots.back() - knots.front()) * i / 50.0;
      // Values O(1..10): 1e-12 is round-off of the fit.
      EXPECT_NEAR(spline->value(s), p(s), 1e-12);
      EXPECT_NEAR(spline->derivative(s), dp(s), 1e-12);
      EXPECT_NEAR(spline->secondDerivative(s), ddp(s), 1e-11);
    }
  }
}

TEST(ContourSpline, InterpolatingIsTheLineOrParabolaThroughFewSamples)
{
  const CubicSpline two = CubicSpline::interpolating({1.0, 3.0}, {2.0, 6.0});
  EXPECT_DOUBLE_EQ(two.derivative(3.0), 2.0);
  EXPECT_DOUBLE_EQ(two.value(2.0), 4.0);
  // Parabola f = t^2 through three uneven samples: slope 2t everywhere (1e-14: round-off
  // of the divided differences of O(1) values).
  const CubicSpline three = CubicSpline::interpolating({0.0, 0.5, 2.0}, {0.0, 0.25, 4.0});
  EXPECT_NEAR(three.derivative(2.0), 4.0, 1e-14);
  EXPECT_NEAR(three.derivative(0.0), 0.0, 1e-14);
  EXPECT_NEAR(three.derivative(1.0), 2.0, 1e-14);
  EXPECT_NEAR(three.value(1.0), 1.0, 1e-14);
  // From four samples on it is the not-a-knot spline.
  const std::vector<double> knots{0.0, 0.3, 0.45, 1.1, 1.2};
  const std::vector<double> values{0.5, -0.1, 0.2, 0.9, 0.4};
  const CubicSpline notAKnot = CubicSpline::notAKnot(knots, values);
  std::vector<CubicPiece> pieces;
  for (int k = 0; k < notAKnot.numberOfPieces(); ++k) {
    pieces.push_back(notAKnot.piece(k));
  }
  expectSamePieces(CubicSpline::interpolating(knots, values), pieces);
  EXPECT_THROW(CubicSpline::interpolating({0.0}, {1.0}), capsula::core::InputError);
  EXPECT_THROW(CubicSpline::interpolating({0.0, 1.0}, {1.0, NAN}), capsula::core::InputError);
}

TEST(ContourSpline, InterpolatingEndSlopeConvergesAtThirdOrder)
{
  // The slope at the LAST sample is what the centroid velocity uses at the newest output
  // time. For a smooth f the not-a-knot end slope error is O(h^3): halving h divides it
  // by ~8.
  std::vector<double> errors;
  for (int n : {8, 16, 32, 64}) {
    std::vector<double> t, f;
    for (int k = 0; k <= n; ++k) {
      t.push_back(2.0 * k / n);
      f.push_back(std::sin(3.0 * t.back()));
    }
    const CubicSpline spline = CubicSpline::interpolating(t, f);
    errors.push_back(std::abs(spline.derivative(2.0) - 3.0 * std::cos(6.0)));
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(errors[k - 1] / errors[k]);
    EXPECT_GT(order, 2.7) << "refinement " << k; // asymptotically 3
  }
  // Size: h^3 |f''''| = (1/32)^3 * 81 = 2.5e-3 times a constant well below 1.
  EXPECT_LT(errors.back(), 5e-4);
}

TEST(ContourSpline, NaturalIsExactForLinesAndHasZeroEndCurvature)
{
  std::mt19937 generator(9);
  const std::vector<double> knots = randomKnots(5, generator);
  std::vector<double> line, wiggle;
  for (double s : knots) {
    line.push_back(1.5 - 0.25 * s);
    wiggle.push_back(std::sin(2.0 * s));
  }
  const CubicSpline straight = CubicSpline::natural(knots, line);
  for (int i = 0; i <= 40; ++i) {
    const double s = knots.front() + (knots.back() - knots.front()) * i / 40.0;
    EXPECT_NEAR(straight.value(s), 1.5 - 0.25 * s, 1e-13);
    EXPECT_NEAR(straight.derivative(s), -0.25, 1e-13);
  }
  const CubicSpline curved = CubicSpline::natural(knots, wiggle);
  EXPECT_NEAR(curved.secondDerivative(knots.front()), 0.0, 1e-13); // eq A.31
  EXPECT_NEAR(curved.secondDerivative(knots.back()), 0.0, 1e-13);  // eq A.32
  EXPECT_GT(std::abs(curved.secondDerivative(knots[2])), 0.1);
}

TEST(ContourSpline, PeriodicReproducesThePeriodicCubicBSpline)
{
  // The uniform cubic B-spline is a C2 piecewise cubic on the knots with values
  // (1/6, 2/3, 1/6) at its three middle knots and 23/48, 1/48 at the half-way points.
  const int n = 8;
  std::vector<double> knots, values(n, 0.0);
  for (int k = 0; k <= n; ++k) {
    knots.push_back(0.5 * k);
  }
  values[1] = 1.0 / 6.0;
  values[2] = 2.0 / 3.0;
  values[3] = 1.0 / 6.0;
  const CubicSpline spline = CubicSpline::periodic(knots, values);
  EXPECT_NEAR(spline.value(0.5 * 1.5), 23.0 / 48.0, 1e-15);
  EXPECT_NEAR(spline.value(0.5 * 2.5), 23.0 / 48.0, 1e-15);
  EXPECT_NEAR(spline.value(0.5 * 0.5), 1.0 / 48.0, 1e-15);
  EXPECT_NEAR(spline.value(0.5 * 5.5), 0.0, 1e-15);
  EXPECT_NEAR(spline.value(0.5 * 4.0), 0.0, 1e-15);
  // Periodicity, also of derivatives, and wrapping of s outside [s_0, s_n).
  EXPECT_NEAR(spline.value(0.3 + 4.0), spline.value(0.3), 1e-15);
  EXPECT_NEAR(spline.value(0.3 - 8.0), spline.value(0.3), 1e-15);
  EXPECT_NEAR(spline.piece(n - 1).derivative(0.5), spline.piece(0).c, 1e-14);
  EXPECT_NEAR(spline.piece(n - 1).secondDerivative(0.5), 2.0 * spline.piece(0).b, 1e-14);
}

TEST(ContourSpline, RejectsBadInput)
{
  using capsula::core::InputError;
  EXPECT_THROW(CubicSpline::natural({0.0, 1.0, 1.0}, {0.0, 1.0, 2.0}), InputError);
  EXPECT_THROW(CubicSpline::natural({0.0, 1.0, 2.0}, {0.0, 1.0}), InputError);
  EXPECT_THROW(CubicSpline::periodic({0.0, 1.0, 2.0}, {0.0, 1.0}), InputError);
  EXPECT_THROW(CubicSpline::notAKnot({0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}), InputError);
  EXPECT_THROW(CubicSpline::periodic({0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 2.0, 3.0}), InputError);
}

} // namespace
