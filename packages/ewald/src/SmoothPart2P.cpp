// The smooth part of the spectral Ewald sum of the Stokeslet (SpectralEwald2P.hpp).
#include "SmoothPartEngine.hpp"

#include "capsula/ewald/ZeroMode2P.hpp"

namespace capsula::ewald {

namespace {

/// The Stokeslet for the engine: sources are forces g.
struct ScreenedStokesletKernel {
  static constexpr int sourceComponents = 3;

  /// u = 8 pi (delta k^2 - k k) / k^4 (1 + k^2/(4 xi^2)) e^{-(1 - eta) k^2 / (4 xi^2)} g.
  static void multiply(const double k[3], double xi, double eta, const std::complex<double>* g, std::complex<double>* u)
  {
    constexpr double stokesletKernelPi = 3.14159265358979323846;
    const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    const double kappa = k2 / (4.0 * xi * xi);
    const double factor = 8.0 * stokesletKernelPi * (1.0 + kappa) * std::exp(-(1.0 - eta) * kappa) / (k2 * k2);
    const std::complex<double> kDotG = k[0] * g[0] + k[1] * g[1] + k[2] * g[2];
    for (int c = 0; c < 3; ++c) {
      u[c] = factor * (k2 * g[c] - k[c] * kDotG);
    }
  }

  /// The inverse transform of 8 pi (1 + k^2/(4 xi^2)) e^{-(1 - eta) k^2/(4 xi^2)} / k^2:
  /// h_{xi'}(y) + eta / (1 - eta) 2 sqrt(pi) / xi' e^{-xi'^2 y^2}, xi' = xi / sqrt(1 - eta).
  static double zeroModeProfile(double y, double xi, double eta)
  {
    constexpr double sqrtPi = 1.77245385090551602730;
    const double xiPrime = xi / std::sqrt(1.0 - eta);
    return smoothZeroModeProfile(y, xiPrime) +
           eta / (1.0 - eta) * 2.0 * sqrtPi / xiPrime * std::exp(-xiPrime * xiPrime * y * y);
  }

  /// The zero mode drives the parallel components only (ZeroMode2P.hpp).
  static void combineZeroMode(const double* convolved, double* u)
  {
    u[0] = convolved[0];
    u[1] = 0.0;
    u[2] = convolved[2];
  }
};

} // namespace

void addSmoothPart2P(const PeriodicLayer& layer, const SpectralEwaldSettings& s, const std::vector<double>& sources,
                     const std::vector<double>& forces, const std::vector<double>& targets,
                     std::vector<double>& velocities)
{
  detail::addSmoothPart<ScreenedStokesletKernel>(layer, s, sources, forces, targets, velocities);
}

} // namespace capsula::ewald
