// The spectral Ewald sum of the stresslet (SpectralEwaldStresslet2P.hpp): its kernel policies
// for the local and smooth engines.
#include "capsula/ewald/SpectralEwaldStresslet2P.hpp"

#include "LocalPartEngine.hpp"
#include "SmoothPartEngine.hpp"
#include "SymmetricTensor.hpp"

#include "capsula/ewald/StressletSplit.hpp"
#include "capsula/ewald/ZeroMode2P.hpp"

#include <stdexcept>

namespace capsula::ewald {

namespace {

using detail::symmetricIndex;
using detail::symmetricTimes;

struct StressletKernel {
  static constexpr int sourceComponents = 6;

  /// u_i += T^R_ijk S_jk = c1 xh_i (xh.S.xh) + c2 (2 (S xh)_i + xh_i tr S); nothing at r = 0.
  static void add(const double xh[3], double r2, double xi, const double* S, double u[3])
  {
    if (r2 == 0.0) {
      return;
    }
    double c1 = 0.0, c2 = 0.0;
    screenedStressletCoefficients(std::sqrt(r2), xi, c1, c2);
    double Sxh[3];
    symmetricTimes(S, xh, Sxh);
    const double xhSxh = xh[0] * Sxh[0] + xh[1] * Sxh[1] + xh[2] * Sxh[2];
    const double trace = S[0] + S[1] + S[2];
    for (int i = 0; i < 3; ++i) {
      u[i] += c1 * xh[i] * xhSxh + c2 * (2.0 * Sxh[i] + xh[i] * trace);
    }
  }

  static void multiply(const double k[3], double xi, double eta, const std::complex<double>* S, std::complex<double>* u)
  {
    constexpr double stressletKernelPi = 3.14159265358979323846;
    const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    const double kappa = k2 / (4.0 * xi * xi);
    const std::complex<double> factor(0.0,
                                      8.0 * stressletKernelPi * (1.0 + kappa) * std::exp(-(1.0 - eta) * kappa) / k2);
    std::complex<double> Sk[3];
    symmetricTimes(S, k, Sk);
    const std::complex<double> kSk = k[0] * Sk[0] + k[1] * Sk[1] + k[2] * Sk[2];
    const std::complex<double> trace = S[0] + S[1] + S[2];
    for (int i = 0; i < 3; ++i) {
      u[i] = factor * (2.0 * Sk[i] + k[i] * trace - 2.0 * k[i] * kSk / k2);
    }
  }

  /// d/dy of the Stokeslet's profile h_{xi'}(y) + eta/(1-eta) 2 sqrt(pi)/xi' e^{-xi'^2 y^2}.
  static double zeroModeProfile(double y, double xi, double eta)
  {
    constexpr double sqrtPi = 1.77245385090551602730;
    const double xiPrime = xi / std::sqrt(1.0 - eta);
    const double gaussian = eta / (1.0 - eta) * 2.0 * sqrtPi / xiPrime * std::exp(-xiPrime * xiPrime * y * y);
    return smoothStressletZeroModeProfile(y, xiPrime) - 2.0 * xiPrime * xiPrime * y * gaussian;
  }

  /// 2 S_xy K and 2 S_zy K on the parallel components, tr(S) K on y (StressletReference2P.hpp).
  static void combineZeroMode(const double* convolved, double* u)
  {
    u[0] = 2.0 * convolved[3];
    u[1] = convolved[0] + convolved[1] + convolved[2];
    u[2] = 2.0 * convolved[5];
  }
};

} // namespace

std::vector<double> spectralEwaldStresslet2P(const PeriodicLayer& layer, double tolerance,
                                             const std::vector<double>& sources, const std::vector<double>& tensors,
                                             const std::vector<double>& targets, double xi)
{
  if (sources.size() % 3 != 0 || tensors.size() != 3 * sources.size() || targets.size() % 3 != 0) {
    throw std::invalid_argument("ewald: sources and targets need 3 numbers per point, tensors 9 per source");
  }
  std::vector<double> velocities(targets.size(), 0.0);
  if (sources.empty() || targets.empty()) {
    return velocities;
  }
  const std::size_t count = sources.size() / 3;
  std::vector<double> symmetric(6 * count);
  for (std::size_t n = 0; n < count; ++n) {
    for (int j = 0; j < 3; ++j) {
      for (int k = j; k < 3; ++k) {
        symmetric[6 * n + symmetricIndex[j][k]] = 0.5 * (tensors[9 * n + 3 * j + k] + tensors[9 * n + 3 * k + j]);
      }
    }
  }
  const SpectralEwaldSettings settings = spectralEwaldSettingsFor(layer, tolerance, sources, targets, xi);
  detail::addLocalPart<StressletKernel>(layer, settings, sources, symmetric, targets, velocities);
  detail::addSmoothPart<StressletKernel>(layer, settings, sources, symmetric, targets, velocities);
  return velocities;
}

} // namespace capsula::ewald
