// JacobianProducts: the least-residual start of a stage solve from kept products (x, J~ x)
// (JacobianProducts.hpp). A small dense J~; every answer is checked against W = I - shift J~
// applied here.
#include <capsula/operators/JacobianProducts.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace jacobian_products_test { // the file's own names, apart from those of the files compiled with it
namespace {

using capsula::operators::JacobianProducts;

constexpr std::size_t kN = 12;

std::vector<double> jacobianTimes(const std::vector<double>& x)
{
  std::vector<double> y(kN, 0.0);
  for (std::size_t i = 0; i < kN; ++i) {
    for (std::size_t j = 0; j < kN; ++j) {
      const double entry = (i == j ? -3.0 - static_cast<double>(i) : 0.0) + 0.2 * std::cos(0.9 * i + 0.4 * j);
      y[i] += entry * x[j];
    }
  }
  return y;
}

std::vector<double> wTimes(double shift, const std::vector<double>& x)
{
  std::vector<double> Jx = jacobianTimes(x), Wx(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    Wx[i] = x[i] - shift * Jx[i];
  }
  return Wx;
}

std::vector<double> vector(double a, double b)
{
  std::vector<double> v(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    v[i] = std::sin(a * static_cast<double>(i) + b);
  }
  return v;
}

void keep(JacobianProducts& products, const std::vector<double>& x)
{
  const std::vector<double> Jx = jacobianTimes(x);
  products.add(x.data(), Jx.data(), kN);
}

double norm(const std::vector<double>& v)
{
  double s = 0.0;
  for (const double x : v) {
    s += x * x;
  }
  return std::sqrt(s);
}

} // namespace

// r = W (2 x_a - 3 x_b) is reached exactly (to round-off, 1e-13 of |r| ~ 10); the returned
// residual is r - W x0 itself, recomputed here.
TEST(JacobianProducts, ReachesARightHandSideInTheirSpan)
{
  JacobianProducts products(8);
  const std::vector<double> a = vector(0.7, 0.1), b = vector(1.9, 0.5);
  keep(products, a);
  keep(products, b);
  const double shift = 0.3;
  const std::vector<double> Wa = wTimes(shift, a), Wb = wTimes(shift, b);
  std::vector<double> r(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    r[i] = 2.0 * Wa[i] - 3.0 * Wb[i];
  }
  std::vector<double> x0, r0;
  const double left = products.minimalResidualGuess(shift, r, x0, r0);
  EXPECT_LT(left, 1e-13 * norm(r));
  for (std::size_t i = 0; i < kN; ++i) {
    EXPECT_NEAR(x0[i], 2.0 * a[i] - 3.0 * b[i], 1e-12);
  }
  const std::vector<double> Wx0 = wTimes(shift, x0);
  for (std::size_t i = 0; i < kN; ++i) {
    EXPECT_NEAR(r0[i], r[i] - Wx0[i], 1e-12);
  }
}

// Outside their span the guess is the least-squares one: its residual is orthogonal to
// every W x_j (normal equations, to 1e-12 of |r| |W x_j|) and no larger than |r|; a copy of
// a kept direction (dependent column) changes nothing.
TEST(JacobianProducts, GivesTheLeastResidualOutsideTheirSpan)
{
  JacobianProducts products(8), withCopy(8);
  const std::vector<std::vector<double>> kept = {vector(0.7, 0.1), vector(1.9, 0.5), vector(0.3, 1.2)};
  for (const auto& x : kept) {
    keep(products, x);
    keep(withCopy, x);
  }
  keep(withCopy, kept[1]);
  const double shift = 0.8;
  const std::vector<double> r = vector(2.6, 0.9);
  std::vector<double> x0, r0, y0, s0;
  const double left = products.minimalResidualGuess(shift, r, x0, r0);
  EXPECT_LT(left, norm(r));
  EXPECT_GT(left, 1e-3 * norm(r)); // r is not in a 3-dimensional span of a 12-dimensional space
  for (const auto& x : kept) {
    const std::vector<double> Wx = wTimes(shift, x);
    double dot = 0.0;
    for (std::size_t i = 0; i < kN; ++i) {
      dot += r0[i] * Wx[i];
    }
    EXPECT_NEAR(dot, 0.0, 1e-12 * norm(r) * norm(Wx));
  }
  EXPECT_NEAR(withCopy.minimalResidualGuess(shift, r, y0, s0), left, 1e-12 * norm(r));
  for (std::size_t i = 0; i < kN; ++i) {
    EXPECT_NEAR(y0[i], x0[i], 1e-10);
  }
}

// Full: a new product replaces the oldest; clear() forgets all; capacity 0 keeps none.
TEST(JacobianProducts, ReplacesTheOldestWhenFull)
{
  JacobianProducts products(2);
  const std::vector<double> a = vector(0.7, 0.1), b = vector(1.9, 0.5), c = vector(0.3, 1.2);
  keep(products, a);
  keep(products, b);
  keep(products, c); // a is gone
  EXPECT_EQ(products.size(), 2u);
  const double shift = 0.3;
  std::vector<double> x0, r0;
  EXPECT_GT(products.minimalResidualGuess(shift, wTimes(shift, a), x0, r0), 1e-3);
  EXPECT_LT(products.minimalResidualGuess(shift, wTimes(shift, c), x0, r0), 1e-12);
  EXPECT_LT(products.minimalResidualGuess(shift, wTimes(shift, b), x0, r0), 1e-12);
  products.clear();
  EXPECT_EQ(products.size(), 0u);
  const std::vector<double> r = wTimes(shift, b);
  EXPECT_EQ(products.minimalResidualGuess(shift, r, x0, r0), norm(r));
  JacobianProducts none(0);
  keep(none, a);
  EXPECT_EQ(none.size(), 0u);
}

} // namespace jacobian_products_test
