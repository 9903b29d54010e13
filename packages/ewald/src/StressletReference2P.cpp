#include "capsula/ewald/StressletReference2P.hpp"

#include "capsula/ewald/LatticeSums2P.hpp"
#include "capsula/ewald/StressletSplit.hpp"
#include "capsula/ewald/ZeroMode2P.hpp"

#include <array>
#include <cmath>
#include <complex>

namespace capsula::ewald {

namespace {

constexpr double stressletPi = 3.14159265358979323846;

/// A polynomial c0 + c1 ky + c2 ky^2 + c3 ky^3 in the free wavenumber ky.
using KyPolynomial = std::array<double, 4>;

KyPolynomial times(const KyPolynomial& p, const KyPolynomial& q)
{
  KyPolynomial r{};
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; a + b < 4; ++b) {
      r[a + b] += p[a] * q[b];
    }
  }
  return r;
}

void zeroTensor(double T[3][3][3])
{
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        T[i][j][k] = 0.0;
      }
    }
  }
}

} // namespace

void periodicStressletReal2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                             double T[3][3][3])
{
  zeroTensor(T);
  forEachImageWithin(layer, truncation.realCutoff, xh, [&](const double shifted[3]) {
    double term[3][3][3];
    screenedStresslet3D(shifted, truncation.xi, term);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          T[i][j][k] += term[i][j][k];
        }
      }
    }
  });
}

void periodicStressletFourier2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                                double T[3][3][3])
{
  zeroTensor(T);
  const double y = xh[1];
  const double area = layer.lengthX * layer.lengthZ;
  const std::complex<double> I(0.0, 1.0);
  forEachModeWithin(layer, truncation.wavenumberCutoff, false, [&](double kx, double kz) {
    const double a2 = kx * kx + kz * kz;
    const ModeProfiles p = modeProfiles(std::sqrt(a2), y, truncation.xi);
    // ky^n acting on J0 is (-i d/dy)^n J0.
    const std::complex<double> kyPowers[4] = {p.j0, -I * p.j0Prime, -p.j0Second, I * p.j0Third};
    const KyPolynomial k[3] = {{kx, 0, 0, 0}, {0, 1, 0, 0}, {kz, 0, 0, 0}};
    const KyPolynomial kSquared{a2, 0, 1, 0};
    const std::complex<double> phase = std::exp(I * (kx * xh[0] + kz * xh[2])) * (8.0 * stressletPi * I / area);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        for (int l = 0; l < 3; ++l) {
          KyPolynomial deltas{};
          for (int n = 0; n < 4; ++n) {
            deltas[n] = (i == l ? k[j][n] : 0.0) + (i == j ? k[l][n] : 0.0) + (j == l ? k[i][n] : 0.0);
          }
          const KyPolynomial first = times(deltas, kSquared);
          const KyPolynomial cubic = times(times(k[i], k[j]), k[l]);
          std::complex<double> value = 0.0;
          for (int n = 0; n < 4; ++n) {
            value += (first[n] - 2.0 * cubic[n]) * kyPowers[n];
          }
          T[i][j][l] += (phase * value).real();
        }
      }
    }
  });
  const double zero = smoothStressletZeroModeProfile(y, truncation.xi) / area;
  for (int par : {0, 2}) {
    T[par][par][1] += zero;
    T[par][1][par] += zero;
    T[1][par][par] += zero;
  }
  T[1][1][1] += zero;
}

void periodicStresslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                         double T[3][3][3])
{
  double fourier[3][3][3];
  periodicStressletReal2P(layer, truncation, xh, T);
  periodicStressletFourier2P(layer, truncation, xh, fourier);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        T[i][j][k] += fourier[i][j][k];
      }
    }
  }
}

} // namespace capsula::ewald
