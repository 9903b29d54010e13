// The fast double layer of the lower wall's stresslet (SpectralEwaldWallStresslet2P.hpp): one
// stresslet sum at the targets and their reflections, and the kernel policies of the two
// Laplace-derivative sums at the reflections.
#include "capsula/ewald/SpectralEwaldWallStresslet2P.hpp"

#include "LocalPartEngine.hpp"
#include "SmoothPartEngine.hpp"
#include "SymmetricTensor.hpp"

#include "capsula/ewald/LaplaceSplit.hpp"
#include "capsula/ewald/SpectralEwald2P.hpp"
#include "capsula/ewald/SpectralEwaldStresslet2P.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

namespace capsula::ewald {

namespace {

using detail::symmetricIndex;
using detail::symmetricTimes;

constexpr double wallDoubleLayerPi = 3.14159265358979323846;

// s = (1, -1, 1): the reflection y -> -y.
constexpr double wallMirrorSign[3] = {1.0, -1.0, 1.0};

/// u_j = s_j d_i d_j d_k (1/r) D_ik for symmetric densities D (A of the header, D = h S).
struct ThirdDerivativeKernel {
  static constexpr int sourceComponents = 6;

  /// d_i d_j d_k phi^R D_ik = f2 (2 (D xh)_j + xh_j tr D) + f3 xh_j (xh.D.xh) (LaplaceSplit.hpp).
  static void add(const double xh[3], double r2, double xi, const double* D, double u[3])
  {
    if (r2 == 0.0) {
      return;
    }
    const double r = std::sqrt(r2);
    double f1 = 0.0, f2 = 0.0;
    screenedLaplaceCoefficients(r, xi, f1, f2);
    const double f3 = screenedLaplaceThirdCoefficient(r, xi);
    double Dxh[3];
    symmetricTimes(D, xh, Dxh);
    const double xhDxh = xh[0] * Dxh[0] + xh[1] * Dxh[1] + xh[2] * Dxh[2];
    const double trace = D[0] + D[1] + D[2];
    for (int j = 0; j < 3; ++j) {
      u[j] += wallMirrorSign[j] * (f2 * (2.0 * Dxh[j] + xh[j] * trace) + f3 * xh[j] * xhDxh);
    }
  }

  /// (i k_i)(i k_j)(i k_k) m D_ik = -i m k_j (k.D.k).
  static void multiply(const double k[3], double xi, double eta, const std::complex<double>* D, std::complex<double>* u)
  {
    std::complex<double> Dk[3];
    symmetricTimes(D, k, Dk);
    const std::complex<double> kDk = k[0] * Dk[0] + k[1] * Dk[1] + k[2] * Dk[2];
    const std::complex<double> factor(0.0, -laplaceSmoothMultiplier(k, xi, eta));
    for (int j = 0; j < 3; ++j) {
      u[j] = wallMirrorSign[j] * factor * k[j] * kDk;
    }
  }

  /// phi_0'''(y) = 8 xi'^3 sqrt(pi) y e^{-xi'^2 y^2}.
  static double zeroModeProfile(double y, double xi, double eta)
  {
    const double xiPrime = windowedXi(xi, eta);
    return 8.0 * xiPrime * xiPrime * xiPrime * std::sqrt(wallDoubleLayerPi) * y * std::exp(-xiPrime * xiPrime * y * y);
  }

  /// Only d_y d_y d_y survives the x-z average: s_y D_yy phi_0'''.
  static void combineZeroMode(const double* convolved, double* u)
  {
    u[0] = 0.0;
    u[1] = -convolved[1];
    u[2] = 0.0;
  }
};

/// u_j = s_j d_j d_y (1/r) q + delta_jy d_i d_k (1/r) S_ik for densities (q, S symmetric): B + C.
struct SecondDerivativeKernel {
  static constexpr int sourceComponents = 7;

  /// d_a d_b phi^R = f1 delta_ab + f2 xh_a xh_b (LaplaceSplit.hpp).
  static void add(const double xh[3], double r2, double xi, const double* qS, double u[3])
  {
    if (r2 == 0.0) {
      return;
    }
    double f1 = 0.0, f2 = 0.0;
    screenedLaplaceCoefficients(std::sqrt(r2), xi, f1, f2);
    const double* S = qS + 1;
    double Sxh[3];
    symmetricTimes(S, xh, Sxh);
    const double xhSxh = xh[0] * Sxh[0] + xh[1] * Sxh[1] + xh[2] * Sxh[2];
    for (int j = 0; j < 3; ++j) {
      u[j] += wallMirrorSign[j] * qS[0] * f2 * xh[j] * xh[1];
    }
    u[1] += -qS[0] * f1 + f1 * (S[0] + S[1] + S[2]) + f2 * xhSxh;
  }

  /// d_a d_b -> -m k_a k_b.
  static void multiply(const double k[3], double xi, double eta, const std::complex<double>* qS,
                       std::complex<double>* u)
  {
    const double m = laplaceSmoothMultiplier(k, xi, eta);
    const std::complex<double>* S = qS + 1;
    std::complex<double> Sk[3];
    symmetricTimes(S, k, Sk);
    const std::complex<double> kSk = k[0] * Sk[0] + k[1] * Sk[1] + k[2] * Sk[2];
    for (int j = 0; j < 3; ++j) {
      u[j] = -wallMirrorSign[j] * m * k[j] * k[1] * qS[0];
    }
    u[1] -= m * kSk;
  }

  /// phi_0''(y) = -4 xi' sqrt(pi) e^{-xi'^2 y^2}.
  static double zeroModeProfile(double y, double xi, double eta)
  {
    const double xiPrime = windowedXi(xi, eta);
    return -4.0 * xiPrime * std::sqrt(wallDoubleLayerPi) * std::exp(-xiPrime * xiPrime * y * y);
  }

  /// Only d_y d_y survives the x-z average: (s_y q + S_yy) phi_0''.
  static void combineZeroMode(const double* convolved, double* u)
  {
    u[0] = 0.0;
    u[1] = convolved[2] - convolved[0];
    u[2] = 0.0;
  }
};

} // namespace

std::vector<double> spectralEwaldWallStresslet2P(const PeriodicLayer& layer, double tolerance,
                                                 const std::vector<double>& sources, const std::vector<double>& tensors,
                                                 const std::vector<double>& targets)
{
  if (sources.size() % 3 != 0 || tensors.size() != 3 * sources.size() || targets.size() % 3 != 0) {
    throw std::invalid_argument("ewald: sources and targets need 3 numbers per point, tensors 9 per source");
  }
  std::vector<double> velocities(targets.size(), 0.0);
  if (sources.empty() || targets.empty()) {
    return velocities;
  }
  const std::size_t count = sources.size() / 3, numTargets = targets.size() / 3;
  std::vector<double> third(6 * count), second(7 * count);
  for (std::size_t n = 0; n < count; ++n) {
    const double h = sources[3 * n + 1];
    if (!(h > 0.0)) {
      throw std::invalid_argument("ewald: wall sources need heights y > 0 above the wall y = 0");
    }
    const double* S = &tensors[9 * n];
    second[7 * n] = S[0] + S[4] + S[8];
    for (int i = 0; i < 3; ++i) {
      for (int k = i; k < 3; ++k) {
        const double symmetric = 0.5 * (S[3 * i + k] + S[3 * k + i]);
        third[6 * n + symmetricIndex[i][k]] = h * symmetric;
        second[7 * n + 1 + symmetricIndex[i][k]] = symmetric;
      }
    }
  }
  // The targets, then their reflections X_t = R x_t.
  std::vector<double> points(2 * targets.size());
  for (std::size_t t = 0; t < numTargets; ++t) {
    if (!(targets[3 * t + 1] >= 0.0)) {
      throw std::invalid_argument("ewald: wall targets need heights y >= 0");
    }
    for (int i = 0; i < 3; ++i) {
      points[3 * t + i] = targets[3 * t + i];
      points[targets.size() + 3 * t + i] = wallMirrorSign[i] * targets[3 * t + i];
    }
  }
  const std::vector<double> stresslet = spectralEwaldStresslet2P(layer, tolerance, sources, tensors, points);
  const std::vector<double> reflected(points.begin() + static_cast<std::ptrdiff_t>(targets.size()), points.end());
  std::vector<double> laplace(targets.size(), 0.0);
  const SpectralEwaldSettings settings = spectralEwaldSettingsFor(layer, tolerance, sources, reflected);
  detail::addLocalPart<ThirdDerivativeKernel>(layer, settings, sources, third, reflected, laplace);
  detail::addSmoothPart<ThirdDerivativeKernel>(layer, settings, sources, third, reflected, laplace);
  detail::addLocalPart<SecondDerivativeKernel>(layer, settings, sources, second, reflected, laplace);
  detail::addSmoothPart<SecondDerivativeKernel>(layer, settings, sources, second, reflected, laplace);
  for (std::size_t t = 0; t < numTargets; ++t) {
    const double y = targets[3 * t + 1];
    for (int j = 0; j < 3; ++j) {
      const std::size_t c = 3 * t + j;
      velocities[c] = -stresslet[c] + stresslet[targets.size() + c] - 4.0 * y * laplace[c];
    }
  }
  return velocities;
}

} // namespace capsula::ewald
