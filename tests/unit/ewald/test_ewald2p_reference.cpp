// The reference 2P Ewald sum of the Stokeslet (Ewald2PReference.hpp): periodic, independent of
// the splitting parameter, symmetric, with the documented zero mode, and equal to a brute-force
// image sum where that converges absolutely.
#include <capsula/ewald/Ewald2PReference.hpp>
#include <capsula/greens/FreeSpace3D.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace capsula::ewald;
constexpr double referencePi = 3.14159265358979323846;

using Tensor = std::vector<double>; // 9 entries, row-major

Tensor periodicG(const PeriodicLayer& layer, double xi, const double xh[3], double tolerance = 1e-16)
{
  double G[3][3];
  periodicStokeslet2P(layer, ewaldTruncation(xi, tolerance), xh, G);
  return {G[0][0], G[0][1], G[0][2], G[1][0], G[1][1], G[1][2], G[2][0], G[2][1], G[2][2]};
}

double maxAbs(const Tensor& t)
{
  double m = 0.0;
  for (double v : t) {
    m = std::max(m, std::fabs(v));
  }
  return m;
}

double maxDifference(const Tensor& a, const Tensor& b)
{
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    m = std::max(m, std::fabs(a[i] - b[i]));
  }
  return m;
}

const PeriodicLayer rectangle{2.0, 1.5};
const double samplePoints[4][3] = {{0.3, 0.1, -0.2}, {-0.9, 0.7, 0.6}, {0.05, -1.8, 0.7}, {1.9, 0.02, 1.4}};

TEST(Ewald2PReference, PeriodicInXAndZ)
{
  // A shift by a lattice vector changes only the rounding of the phases (1e-15 relative).
  for (const auto& xh : samplePoints) {
    const Tensor G = periodicG(rectangle, 1.5, xh);
    const double shifts[3][2] = {{1, 0}, {0, 1}, {3, -2}};
    for (const auto& s : shifts) {
      const double moved[3] = {xh[0] + s[0] * rectangle.lengthX, xh[1], xh[2] + s[1] * rectangle.lengthZ};
      EXPECT_LT(maxDifference(periodicG(rectangle, 1.5, moved), G), 1e-13 * maxAbs(G));
    }
  }
}

TEST(Ewald2PReference, IndependentOfTheSplittingParameter)
{
  // The split moves weight between the local and the smooth sums; their total is the same to
  // the truncation tolerance (1e-16 here) plus rounding: 1e-12 of |G| over a factor 4 in xi.
  // The local parts alone differ by >1e-2 between these xi (checked), 1e10 times the tolerance.
  for (const auto& xh : samplePoints) {
    const Tensor reference = periodicG(rectangle, 1.0, xh);
    for (double xi : {2.0, 4.0}) {
      EXPECT_LT(maxDifference(periodicG(rectangle, xi, xh), reference), 1e-12 * maxAbs(reference)) << "xi " << xi;
    }
    double real1[3][3], real4[3][3];
    periodicStokesletReal2P(rectangle, ewaldTruncation(1.0, 1e-16), xh, real1);
    periodicStokesletReal2P(rectangle, ewaldTruncation(4.0, 1e-16), xh, real4);
    EXPECT_GT(std::fabs(real1[0][0] - real4[0][0]), 1e-2);
  }
}

TEST(Ewald2PReference, TruncationErrorIsBelowTheTolerance)
{
  // ewaldTruncation's r_c and k_c leave out terms below tol relative to |G| (the e^{-2} margin
  // covers the prefactors of the neglected images and modes); measured against tol = 1e-16 over
  // xi = 0.8..3 and tol = 1e-4..1e-10.
  for (const auto& xh : samplePoints) {
    for (double xi : {0.8, 3.0}) {
      const Tensor exact = periodicG(rectangle, xi, xh);
      for (double tolerance : {1e-4, 1e-7, 1e-10}) {
        EXPECT_LT(maxDifference(periodicG(rectangle, xi, xh, tolerance), exact), tolerance * maxAbs(exact))
            << "xi " << xi << " tolerance " << tolerance;
      }
    }
  }
}

TEST(Ewald2PReference, SymmetricUnderExchangeOfFieldPointAndPole)
{
  // Lorentz reciprocity G_ij(x, x0) = G_ji(x0, x), i.e. G_ij(xh) = G_ji(-xh); the off-diagonal
  // parallel-y entries are odd in the phase and in y separately, so a sign slip there fails.
  for (const auto& xh : samplePoints) {
    const double minus[3] = {-xh[0], -xh[1], -xh[2]};
    const Tensor G = periodicG(rectangle, 1.5, xh);
    const Tensor H = periodicG(rectangle, 1.5, minus);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(G[3 * i + j], H[3 * j + i], 1e-13 * maxAbs(G));
        EXPECT_NEAR(G[3 * i + j], G[3 * j + i], 1e-13 * maxAbs(G));
      }
    }
  }
}

TEST(Ewald2PReference, AverageOverTheCellIsTheDocumentedZeroMode)
{
  // The x-z average of G is -4 pi |y| / A on the parallel components and 0 elsewhere
  // (ZeroMode2P.hpp). The 24 x 24 trapezoidal average of a periodic function is exact up to the
  // modes |k| >= 24 * 2 pi / L, which decay like e^{-|k| |y|} < 1e-20 at |y| >= 0.7.
  const double area = rectangle.lengthX * rectangle.lengthZ;
  for (double y : {0.7, -1.3, 3.0}) {
    Tensor average(9, 0.0);
    const int n = 24;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        const double xh[3] = {a * rectangle.lengthX / n, y, b * rectangle.lengthZ / n};
        const Tensor G = periodicG(rectangle, 1.5, xh, 1e-14);
        for (int e = 0; e < 9; ++e) {
          average[e] += G[e] / (n * n);
        }
      }
    }
    const double parallel = -4.0 * referencePi * std::fabs(y) / area;
    const Tensor expected{parallel, 0, 0, 0, 0, 0, 0, 0, parallel};
    EXPECT_LT(maxDifference(average, expected), 1e-11) << "y " << y;
  }
}

/// u(x) of forces g_n at poles x_n in G units: sum_n G(x - x_n) g_n.
template <class Kernel>
std::vector<double> fieldOf(const Kernel& kernel, const std::vector<std::vector<double>>& poles,
                            const std::vector<std::vector<double>>& forces, const double x[3])
{
  std::vector<double> u(3, 0.0);
  for (std::size_t n = 0; n < poles.size(); ++n) {
    const double xh[3] = {x[0] - poles[n][0], x[1] - poles[n][1], x[2] - poles[n][2]};
    double G[3][3];
    kernel(xh, G);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        u[i] += G[i][j] * forces[n][j];
      }
    }
  }
  return u;
}

TEST(Ewald2PReference, ForceFreePairTendsToItsFreeSpaceFieldAsThePeriodsGrow)
{
  // A force dipole (g at y = 0.5, -g at y = -0.5) in an L x L layer: the periodic field differs
  // from the free-space one by the images' dipole fields D(x - p). D is homogeneous of degree -2
  // and odd in the plane of the images, so the lattice cancels the leading terms D(-p) pairwise
  // (p, -p) and leaves x . grad D(-p) ~ |x| d / |p|^3, summed absolutely: the difference falls
  // like 1 / L^3, by 8 per doubling of L (measured 7.85 and 7.96); 1/L^2 (a wrong zero mode) or
  // no convergence fails.
  const std::vector<std::vector<double>> poles{{0.0, 0.5, 0.0}, {0.0, -0.5, 0.0}};
  const std::vector<std::vector<double>> forces{{1.0, 0.3, -0.4}, {-1.0, -0.3, 0.4}};
  const double x[3] = {0.4, 1.1, -0.3};
  const auto freeSpace = fieldOf(
      [](const double xh[3], double G[3][3]) { capsula::greens::stokesletFreeSpace3D(xh, G); }, poles, forces, x);
  std::vector<double> errors;
  for (double L : {8.0, 16.0, 32.0}) {
    const PeriodicLayer square{L, L};
    const auto truncation = ewaldTruncation(0.5, 1e-15);
    const auto periodic = fieldOf(
        [&](const double xh[3], double G[3][3]) { periodicStokeslet2P(square, truncation, xh, G); }, poles, forces, x);
    errors.push_back(maxDifference(periodic, freeSpace));
  }
  for (std::size_t e = 1; e < errors.size(); ++e) {
    const double ratio = errors[e - 1] / errors[e];
    EXPECT_GT(ratio, 7.0) << "errors " << errors[e - 1] << " " << errors[e];
    EXPECT_LT(ratio, 9.0) << "errors " << errors[e - 1] << " " << errors[e];
  }
}

TEST(Ewald2PReference, ForceFreeFieldIsBoundedAndTendsToTheDocumentedConstant)
{
  // Forces g_n at heights y_n with sum g_n = 0: far above and below the layer of sources the
  // field tends to +(4 pi / A) sign(y) sum g_n y_n on the parallel components and to 0 on y
  // (ZeroMode2P.hpp); the other modes decay like e^{-2 pi |y| / L} < 1e-13 at |y| = 12.
  const PeriodicLayer square{2.0, 2.0};
  const std::vector<std::vector<double>> poles{{0.1, 0.3, 0.2}, {1.2, -0.4, 1.5}, {0.7, 0.9, -0.6}};
  const std::vector<std::vector<double>> forces{{1.0, 0.4, -0.2}, {-0.3, -0.9, 0.7}, {-0.7, 0.5, -0.5}};
  const auto truncation = ewaldTruncation(1.0, 1e-16);
  const double area = square.lengthX * square.lengthZ;
  for (double sign : {1.0, -1.0}) {
    double moment[3] = {0.0, 0.0, 0.0};
    for (std::size_t n = 0; n < poles.size(); ++n) {
      for (int i = 0; i < 3; ++i) {
        moment[i] += forces[n][i] * poles[n][1];
      }
    }
    const double x[3] = {0.5, sign * 12.0, 0.3};
    const auto u = fieldOf([&](const double xh[3], double G[3][3]) { periodicStokeslet2P(square, truncation, xh, G); },
                           poles, forces, x);
    const double expected[3] = {4.0 * referencePi / area * sign * moment[0], 0.0,
                                4.0 * referencePi / area * sign * moment[2]};
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(u[i], expected[i], 1e-11) << "sign " << sign << " component " << i;
    }
  }
}

/// The image sum of a force-free quadrupole (g, -2g, g at x0 - e, x0, x0 + e) over the images
/// within the disc |p| <= R: it converges absolutely (the field falls like 1/|p|^3).
std::vector<double> imageSumOfQuadrupole(const PeriodicLayer& layer, const double x[3], double R,
                                         const std::vector<std::vector<double>>& poles,
                                         const std::vector<std::vector<double>>& forces)
{
  std::vector<double> u(3, 0.0);
  const int mMax = static_cast<int>(R / layer.lengthX) + 1;
  const int nMax = static_cast<int>(R / layer.lengthZ) + 1;
  for (int m = -mMax; m <= mMax; ++m) {
    for (int n = -nMax; n <= nMax; ++n) {
      const double px = m * layer.lengthX, pz = n * layer.lengthZ;
      if (px * px + pz * pz > R * R) {
        continue;
      }
      const double shifted[3] = {x[0] - px, x[1], x[2] - pz};
      const auto term =
          fieldOf([](const double xh[3], double G[3][3]) { capsula::greens::stokesletFreeSpace3D(xh, G); }, poles,
                  forces, shifted);
      for (int i = 0; i < 3; ++i) {
        u[i] += term[i];
      }
    }
  }
  return u;
}

TEST(Ewald2PReference, AgreesWithTheBruteForceImageSumOfAForceFreeQuadrupole)
{
  // The disc sums' tail falls like 1/R (the 1/|p|^3 field over rings of area 2 pi |p| d|p|), so
  // two radii extrapolate it away (the rest is O(1/R^2) ~ 1e-8 of the field here); the quadrupole
  // along x has zero x-z average, as the Ewald sum's zero mode gives it. Agreement to 1e-6 of
  // the field fails on any wrong term of the mode sum (each moves u by >1e-3).
  const std::vector<std::vector<double>> poles{{-0.25, 0.2, 0.1}, {0.0, 0.2, 0.1}, {0.25, 0.2, 0.1}};
  const std::vector<std::vector<double>> forces{{0.4, 1.0, -0.5}, {-0.8, -2.0, 1.0}, {0.4, 1.0, -0.5}};
  const double x[3] = {0.7, -0.4, 0.5};
  const auto near = imageSumOfQuadrupole(rectangle, x, 150.0, poles, forces);
  const auto far = imageSumOfQuadrupole(rectangle, x, 300.0, poles, forces);
  std::vector<double> extrapolated(3);
  for (int i = 0; i < 3; ++i) {
    extrapolated[i] = 2.0 * far[i] - near[i];
  }
  const auto truncation = ewaldTruncation(1.2, 1e-15);
  const auto ewald = fieldOf(
      [&](const double xh[3], double G[3][3]) { periodicStokeslet2P(rectangle, truncation, xh, G); }, poles, forces, x);
  const double scale = std::max({std::fabs(ewald[0]), std::fabs(ewald[1]), std::fabs(ewald[2])});
  EXPECT_LT(maxDifference(ewald, extrapolated), 1e-6 * scale)
      << "ewald " << ewald[0] << " " << ewald[1] << " " << ewald[2] << "; images " << extrapolated[0] << " "
      << extrapolated[1] << " " << extrapolated[2];
}

} // namespace
