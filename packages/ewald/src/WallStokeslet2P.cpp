#include "capsula/ewald/WallStokeslet2P.hpp"

#include "capsula/ewald/LaplaceSplit.hpp"
#include "capsula/ewald/LatticeSums2P.hpp"

#include <algorithm>
#include <cmath>

namespace capsula::ewald {

namespace {

constexpr double wallPi = 3.14159265358979323846;
constexpr double wallInvSqrtPi = 0.56418958354775628695;

/// The local part: the images within r_c of d phi^R and d d phi^R (LaplaceSplit.hpp).
void addLaplaceReal2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double X[3],
                      double gradient[3], double hessian[3][3])
{
  forEachImageWithin(layer, truncation.realCutoff, X, [&](const double shifted[3]) {
    double g[3], H[3][3];
    screenedLaplaceDerivatives3D(shifted, truncation.xi, g, H);
    for (int i = 0; i < 3; ++i) {
      gradient[i] += g[i];
      for (int j = 0; j < 3; ++j) {
        hessian[i][j] += H[i][j];
      }
    }
  });
}

/// The smooth part: per mode e^{i theta} pi P / a (LaplaceSplit.hpp) differentiated, with
/// d_x, d_z -> i k and d_y through P' = a D, D' = a P - 4 xi g / sqrt(pi); the pair +-(kx, kz)
/// gives cos theta on even and -sin theta on odd orders of the parallel derivatives. The zero
/// mode phi_0 = -2 pi [Y erf(xi Y) + e^{-xi^2 Y^2} / (sqrt(pi) xi)] / A (the 1D potential of the
/// x-z averaged Gaussian) adds phi_0' = -2 pi erf(xi Y) / A and phi_0'' = -4 xi sqrt(pi) e^{-xi^2 Y^2} / A.
void addLaplaceFourier2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double X[3],
                         double gradient[3], double hessian[3][3])
{
  const double xi = truncation.xi;
  const double area = layer.lengthX * layer.lengthZ;
  const double Y = X[1];
  double g[3] = {0.0, 0.0, 0.0}, H[3][3] = {{0.0}};
  forEachModeWithin(layer, truncation.wavenumberCutoff, true, [&](double kx, double kz) {
    const double a = std::sqrt(kx * kx + kz * kz);
    const ModeExponentials e = modeExponentials(a, Y, xi);
    const double theta = kx * X[0] + kz * X[2];
    const double c = 2.0 * std::cos(theta);
    const double s = -2.0 * std::sin(theta);
    const double kPar[3] = {kx, 0.0, kz};
    const double potential = e.sum / a;
    for (int i : {0, 2}) {
      g[i] += s * kPar[i] * potential;
      for (int j : {0, 2}) {
        H[i][j] -= c * kPar[i] * kPar[j] * potential;
      }
      H[i][1] += s * kPar[i] * e.difference;
      H[1][i] += s * kPar[i] * e.difference;
    }
    g[1] += c * e.difference;
    H[1][1] += c * (a * e.sum - 4.0 * xi * wallInvSqrtPi * e.gauss);
  });
  for (int i = 0; i < 3; ++i) {
    gradient[i] += wallPi * g[i] / area;
    for (int j = 0; j < 3; ++j) {
      hessian[i][j] += wallPi * H[i][j] / area;
    }
  }
  gradient[1] -= 2.0 * wallPi * std::erf(xi * Y) / area;
  hessian[1][1] -= 4.0 * xi * std::sqrt(wallPi) * std::exp(-xi * xi * Y * Y) / area;
}

} // namespace

double wallZeroModeProfile(double y, double h)
{
  return 8.0 * wallPi * std::min(y, h);
}

void periodicLaplaceDerivatives2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double X[3],
                                  double gradient[3], double hessian[3][3])
{
  for (int i = 0; i < 3; ++i) {
    gradient[i] = 0.0;
    for (int j = 0; j < 3; ++j) {
      hessian[i][j] = 0.0;
    }
  }
  addLaplaceReal2P(layer, truncation, X, gradient, hessian);
  addLaplaceFourier2P(layer, truncation, X, gradient, hessian);
}

void periodicWallStokeslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double x[3],
                             const double x0[3], double G[3][3])
{
  const double h = x0[1];
  const double y = x[1];
  const double xh[3] = {x[0] - x0[0], y - h, x[2] - x0[2]};
  const double X[3] = {xh[0], y + h, xh[2]};
  double image[3][3], gradient[3], hessian[3][3];
  periodicStokeslet2P(layer, truncation, xh, G);
  periodicStokeslet2P(layer, truncation, X, image);
  periodicLaplaceDerivatives2P(layer, truncation, X, gradient, hessian);
  constexpr int normal = 1;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double s = j == normal ? -1.0 : 1.0;
      const double doubletRest = (j == normal ? gradient[i] : 0.0) - (i == normal ? gradient[j] : 0.0);
      G[i][j] += -image[i][j] + 2.0 * h * s * (y * hessian[i][j] + doubletRest);
    }
  }
}

} // namespace capsula::ewald
