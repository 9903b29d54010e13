#include "capsula/ewald/WallStresslet2P.hpp"

#include "capsula/ewald/LaplaceSplit.hpp"
#include "capsula/ewald/LatticeSums2P.hpp"
#include "capsula/ewald/StressletReference2P.hpp"
#include "capsula/ewald/WallStokeslet2P.hpp"

#include <cmath>

namespace capsula::ewald {

namespace {

constexpr double wallStressPi = 3.14159265358979323846;
constexpr double wallStressInvSqrtPi = 0.56418958354775628695;

/// The smooth part: per mode e^{i theta} F_n(Y), n the number of y indices, times i k_p for
/// each parallel index p, with F_0 = pi P / a, F_1 = pi D, F_2 = pi (a P - 4 xi g / sqrt(pi)),
/// F_3 = pi (a^2 D + 8 xi^3 Y g / sqrt(pi)) (P' = a D, D' = a P - 4 xi g / sqrt(pi),
/// g' = -2 xi^2 Y g). The pair +-(kx, kz) gives 2 Re(i^m e^{i theta}) = 2 cos(theta + m pi / 2)
/// for m parallel indices. The zero mode phi_0''' = 8 xi^3 sqrt(pi) Y e^{-xi^2 Y^2} / A cancels
/// the local part's average.
void addLaplaceThirdFourier2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double X[3],
                              double third[3][3][3])
{
  const double xi = truncation.xi;
  const double area = layer.lengthX * layer.lengthZ;
  const double Y = X[1];
  forEachModeWithin(layer, truncation.wavenumberCutoff, true, [&](double kx, double kz) {
    const double a = std::sqrt(kx * kx + kz * kz);
    const ModeExponentials e = modeExponentials(a, Y, xi);
    const double gaussTerm = wallStressInvSqrtPi * xi * e.gauss;
    const double profile[4] = {e.sum / a, e.difference, a * e.sum - 4.0 * gaussTerm,
                               a * a * e.difference + 8.0 * xi * xi * Y * gaussTerm};
    const double theta = kx * X[0] + kz * X[2];
    const double phase[4] = {2.0 * std::cos(theta), -2.0 * std::sin(theta), -2.0 * std::cos(theta),
                             2.0 * std::sin(theta)};
    const double k[3] = {kx, 1.0, kz}; // the y "wavenumber" 1: its derivative is in the profile
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int l = 0; l < 3; ++l) {
          const int ys = (i == 1) + (j == 1) + (l == 1);
          third[i][j][l] += wallStressPi / area * phase[3 - ys] * k[i] * k[j] * k[l] * profile[ys];
        }
      }
    }
  });
  third[1][1][1] += 8.0 * xi * xi * xi * std::sqrt(wallStressPi) * Y * std::exp(-xi * xi * Y * Y) / area;
}

} // namespace

void periodicLaplaceThirdDerivatives2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double X[3],
                                       double third[3][3][3])
{
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        third[i][j][k] = 0.0;
      }
    }
  }
  forEachImageWithin(layer, truncation.realCutoff, X, [&](const double shifted[3]) {
    double term[3][3][3];
    screenedLaplaceThirdDerivatives3D(shifted, truncation.xi, term);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          third[i][j][k] += term[i][j][k];
        }
      }
    }
  });
  addLaplaceThirdFourier2P(layer, truncation, X, third);
}

void periodicWallStresslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double x[3],
                             const double x0[3], double T[3][3][3])
{
  const double h = x0[1];
  const double y = x[1];
  const double xh[3] = {x[0] - x0[0], y - h, x[2] - x0[2]};
  const double X[3] = {xh[0], y + h, xh[2]};
  double image[3][3][3], third[3][3][3], gradient[3], hessian[3][3];
  periodicStresslet2P(layer, truncation, xh, T);
  periodicStresslet2P(layer, truncation, X, image);
  periodicLaplaceThirdDerivatives2P(layer, truncation, X, third);
  periodicLaplaceDerivatives2P(layer, truncation, X, gradient, hessian);
  constexpr int normal = 1;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double s = j == normal ? -1.0 : 1.0;
      for (int k = 0; k < 3; ++k) {
        const double doubletRest = (i == k ? hessian[j][normal] : 0.0) - (j == normal ? hessian[i][k] : 0.0);
        T[i][j][k] += -image[i][j][k] + 4.0 * h * s * (y * third[i][j][k] - doubletRest);
      }
    }
  }
}

} // namespace capsula::ewald
