// The spectral Ewald sum of the lower wall's Stokeslet (SpectralEwaldWall2P.hpp): the image
// points and densities, and the kernel policies of the two Laplace-derivative sums.
#include "capsula/ewald/SpectralEwaldWall2P.hpp"

#include "LocalPartEngine.hpp"
#include "SmoothPartEngine.hpp"

#include "capsula/ewald/LaplaceSplit.hpp"
#include "capsula/ewald/SpectralEwald2P.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace capsula::ewald {

namespace {

constexpr double laplaceKernelPi = 3.14159265358979323846;

/// u = grad (d . grad phi) for dipole densities d (3 components).
struct DipoleGradientKernel {
  static constexpr int sourceComponents = 3;

  static void add(const double xh[3], double r2, double xi, const double* d, double u[3])
  {
    if (r2 == 0.0) {
      return;
    }
    double f1 = 0.0, f2 = 0.0;
    screenedLaplaceCoefficients(std::sqrt(r2), xi, f1, f2);
    const double xhd = xh[0] * d[0] + xh[1] * d[1] + xh[2] * d[2];
    for (int i = 0; i < 3; ++i) {
      u[i] += f1 * d[i] + f2 * xh[i] * xhd;
    }
  }

  static void multiply(const double k[3], double xi, double eta, const std::complex<double>* d, std::complex<double>* u)
  {
    const std::complex<double> kd = k[0] * d[0] + k[1] * d[1] + k[2] * d[2];
    const double m = laplaceSmoothMultiplier(k, xi, eta);
    for (int i = 0; i < 3; ++i) {
      u[i] = -m * k[i] * kd;
    }
  }

  /// phi_0''(y) = -4 xi' sqrt(pi) e^{-xi'^2 y^2}.
  static double zeroModeProfile(double y, double xi, double eta)
  {
    const double xiPrime = windowedXi(xi, eta);
    return -4.0 * xiPrime * std::sqrt(laplaceKernelPi) * std::exp(-xiPrime * xiPrime * y * y);
  }

  static void combineZeroMode(const double* convolved, double* u)
  {
    u[0] = 0.0;
    u[1] = convolved[1];
    u[2] = 0.0;
  }
};

/// u = q grad phi - e_y (d . grad phi) for densities (d_x, d_y, d_z, q).
struct DoubletRestKernel {
  static constexpr int sourceComponents = 4;

  static void add(const double xh[3], double r2, double xi, const double* dq, double u[3])
  {
    if (r2 == 0.0) {
      return;
    }
    double f1 = 0.0, f2 = 0.0;
    screenedLaplaceCoefficients(std::sqrt(r2), xi, f1, f2);
    for (int i = 0; i < 3; ++i) {
      u[i] += dq[3] * f1 * xh[i];
    }
    u[1] -= f1 * (xh[0] * dq[0] + xh[1] * dq[1] + xh[2] * dq[2]);
  }

  static void multiply(const double k[3], double xi, double eta, const std::complex<double>* dq,
                       std::complex<double>* u)
  {
    const std::complex<double> im(0.0, laplaceSmoothMultiplier(k, xi, eta));
    for (int i = 0; i < 3; ++i) {
      u[i] = im * k[i] * dq[3];
    }
    u[1] -= im * (k[0] * dq[0] + k[1] * dq[1] + k[2] * dq[2]);
  }

  /// phi_0'(y) = -2 pi erf(xi' y).
  static double zeroModeProfile(double y, double xi, double eta)
  {
    return -2.0 * laplaceKernelPi * std::erf(windowedXi(xi, eta) * y);
  }

  static void combineZeroMode(const double* convolved, double* u)
  {
    u[0] = 0.0;
    u[1] = convolved[3] - convolved[1];
    u[2] = 0.0;
  }
};

/// The image points, the Stokeslet forces of sources and images, and the Laplace densities.
struct WallImages {
  std::vector<double> stokesletPoints, stokesletForces; // sources then images, forces g then -g
  std::vector<double> imagePoints, dipoles, dipolesAndSources;
};

WallImages wallImages(const std::vector<double>& sources, const std::vector<double>& forces)
{
  const std::size_t count = sources.size() / 3;
  WallImages w;
  w.stokesletPoints = sources;
  w.stokesletForces = forces;
  for (std::size_t n = 0; n < count; ++n) {
    const double h = sources[3 * n + 1];
    if (!(h > 0.0)) {
      throw std::invalid_argument("ewald: wall sources need heights y > 0 above the wall y = 0");
    }
    const double image[3] = {sources[3 * n], -h, sources[3 * n + 2]};
    const double* g = &forces[3 * n];
    const double d[3] = {2.0 * h * g[0], -2.0 * h * g[1], 2.0 * h * g[2]};
    w.stokesletPoints.insert(w.stokesletPoints.end(), image, image + 3);
    w.imagePoints.insert(w.imagePoints.end(), image, image + 3);
    for (int i = 0; i < 3; ++i) {
      w.stokesletForces.push_back(-g[i]);
      w.dipoles.push_back(d[i]);
      w.dipolesAndSources.push_back(d[i]);
    }
    w.dipolesAndSources.push_back(-2.0 * h * g[1]);
  }
  return w;
}

} // namespace

std::vector<double> spectralEwaldWall2P(const PeriodicLayer& layer, double tolerance,
                                        const std::vector<double>& sources, const std::vector<double>& forces,
                                        const std::vector<double>& targets, double xi)
{
  if (sources.size() % 3 != 0 || forces.size() != sources.size() || targets.size() % 3 != 0) {
    throw std::invalid_argument("ewald: sources, forces and targets need 3 numbers per point, one force per source");
  }
  std::vector<double> velocities(targets.size(), 0.0);
  if (sources.empty() || targets.empty()) {
    return velocities;
  }
  const WallImages w = wallImages(sources, forces);
  // One grid for all three sums: the heights of the targets, the sources and their images.
  const SpectralEwaldSettings settings = spectralEwaldSettingsFor(layer, tolerance, w.stokesletPoints, targets, xi);
  addLocalPart2P(layer, settings, w.stokesletPoints, w.stokesletForces, targets, velocities);
  addSmoothPart2P(layer, settings, w.stokesletPoints, w.stokesletForces, targets, velocities);
  std::vector<double> dipoleField(targets.size(), 0.0);
  detail::addLocalPart<DipoleGradientKernel>(layer, settings, w.imagePoints, w.dipoles, targets, dipoleField);
  detail::addSmoothPart<DipoleGradientKernel>(layer, settings, w.imagePoints, w.dipoles, targets, dipoleField);
  detail::addLocalPart<DoubletRestKernel>(layer, settings, w.imagePoints, w.dipolesAndSources, targets, velocities);
  detail::addSmoothPart<DoubletRestKernel>(layer, settings, w.imagePoints, w.dipolesAndSources, targets, velocities);
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    for (int i = 0; i < 3; ++i) {
      velocities[t + i] += targets[t + 1] * dipoleField[t + i];
    }
  }
  return velocities;
}

} // namespace capsula::ewald
