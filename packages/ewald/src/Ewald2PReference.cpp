#include "capsula/ewald/Ewald2PReference.hpp"

#include "capsula/ewald/EwaldSplit.hpp"
#include "capsula/ewald/LatticeSums2P.hpp"
#include "capsula/ewald/ZeroMode2P.hpp"

#include <cmath>
#include <stdexcept>

namespace capsula::ewald {

namespace {

constexpr double referenceSumPi = 3.14159265358979323846;
constexpr double invSqrtPi = 0.56418958354775628695;

/// erfcx(z) = e^{z^2} erfc(z) for z >= 0: directly while erfc(z) is a normal number, beyond
/// that the asymptotic series (its first omitted term is below 1e-11 relative at z = 25).
double scaledErfc(double z)
{
  if (z < 25.0) {
    return std::exp(z * z) * std::erfc(z);
  }
  const double t = 1.0 / (2.0 * z * z);
  return invSqrtPi / z * (1.0 - t * (1.0 - 3.0 * t * (1.0 - 5.0 * t)));
}

/// e^{s} erfc(z) where s - z^2 = logGauss (both E+- of the header have this form): through
/// erfcx where e^{s} alone could overflow.
double expTimesErfc(double s, double z, double gauss)
{
  if (z > 0.5) {
    return scaledErfc(z) * gauss;
  }
  return std::exp(s) * std::erfc(z);
}

void addScaled(double G[3][3], const double add[3][3], double scale = 1.0)
{
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] += scale * add[i][j];
    }
  }
}

void setZero(double G[3][3])
{
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] = 0.0;
    }
  }
}

} // namespace

EwaldTruncation ewaldTruncation(double xi, double tolerance)
{
  if (!(xi > 0.0) || !(tolerance > 0.0) || !(tolerance < 1.0)) {
    throw std::invalid_argument("ewald: xi > 0 and 0 < tolerance < 1 are needed");
  }
  const double logInverse = std::sqrt(std::log(1.0 / tolerance) + 2.0);
  return {xi, logInverse / xi, 2.0 * xi * logInverse};
}

ModeExponentials modeExponentials(double a, double y, double xi)
{
  const double gauss = std::exp(-a * a / (4.0 * xi * xi) - xi * xi * y * y);
  const double ePlus = expTimesErfc(a * y, a / (2.0 * xi) + xi * y, gauss);
  const double eMinus = expTimesErfc(-a * y, a / (2.0 * xi) - xi * y, gauss);
  return {ePlus + eMinus, ePlus - eMinus, gauss};
}

ModeProfiles modeProfiles(double a, double y, double xi)
{
  const ModeExponentials e = modeExponentials(a, y, xi);
  const double sum = e.sum;
  const double difference = e.difference;
  const double gauss = e.gauss;
  ModeProfiles p;
  p.j0 = sum / (8.0 * a * a * a) - y * difference / (8.0 * a * a) + invSqrtPi * gauss / (4.0 * xi * a * a);
  p.j0Prime = -y * sum / (8.0 * a);
  p.j0Second = -sum / (8.0 * a) - y * difference / 8.0;
  p.j0Third = -difference / 4.0 - y * a * sum / 8.0 + 0.5 * invSqrtPi * xi * y * gauss;
  return p;
}

void periodicStokesletReal2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                             double G[3][3])
{
  setZero(G);
  forEachImageWithin(layer, truncation.realCutoff, xh, [&](const double shifted[3]) {
    double term[3][3];
    screenedStokeslet3D(shifted, truncation.xi, term);
    addScaled(G, term);
  });
}

void periodicStokesletFourier2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                                double G[3][3])
{
  setZero(G);
  const double xi = truncation.xi;
  const double area = layer.lengthX * layer.lengthZ;
  const double y = xh[1];
  // The modes (kx, kz) and (-kx, -kz) together give real terms: cos on the even entries and
  // -sin (from i e^{i theta}) on the parallel-y ones; half of the plane is summed, doubled.
  forEachModeWithin(layer, truncation.wavenumberCutoff, true, [&](double kx, double kz) {
    const double a2 = kx * kx + kz * kz;
    const ModeProfiles p = modeProfiles(std::sqrt(a2), y, xi);
    const double theta = kx * xh[0] + kz * xh[2];
    const double c = 2.0 * std::cos(theta);
    const double s = -2.0 * std::sin(theta);
    const double kPar[3] = {kx, 0.0, kz};
    for (int i : {0, 2}) {
      for (int j : {0, 2}) {
        G[i][j] += c * (-kPar[i] * kPar[j] * p.j0 + (i == j ? a2 * p.j0 - p.j0Second : 0.0));
      }
      G[i][1] += s * kPar[i] * p.j0Prime;
      G[1][i] += s * kPar[i] * p.j0Prime;
    }
    G[1][1] += c * a2 * p.j0;
  });
  const double zero = smoothZeroModeProfile(y, xi);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] *= 8.0 * referenceSumPi / area;
    }
  }
  G[0][0] += zero / area;
  G[2][2] += zero / area;
}

void periodicStokeslet2P(const PeriodicLayer& layer, const EwaldTruncation& truncation, const double xh[3],
                         double G[3][3])
{
  double fourier[3][3];
  periodicStokesletReal2P(layer, truncation, xh, G);
  periodicStokesletFourier2P(layer, truncation, xh, fourier);
  addScaled(G, fourier);
}

} // namespace capsula::ewald
