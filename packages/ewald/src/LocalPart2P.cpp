// The local part of the spectral Ewald sum of the Stokeslet (SpectralEwald2P.hpp).
#include "LocalPartEngine.hpp"

#include "capsula/ewald/EwaldSplit.hpp"

namespace capsula::ewald {

namespace {

/// G^R for the engine: sources are forces g.
struct LocalStokesletKernel {
  static constexpr int sourceComponents = 3;

  static void add(const double xh[3], double r2, double xi, const double* g, double u[3])
  {
    if (r2 == 0.0) {
      // A target on the source: the limit of G^R - G_free = -G^F_free, whose value at the pole
      // is 4 xi / sqrt(pi) delta (EwaldSplit.hpp), so that the whole sum gives lim (G - G_free).
      for (int i = 0; i < 3; ++i) {
        u[i] -= smoothStokesletAtPole(xi) * g[i];
      }
      return;
    }
    double a = 0.0, b = 0.0;
    screenedStokesletCoefficients(std::sqrt(r2), xi, a, b);
    const double xhDotG = xh[0] * g[0] + xh[1] * g[1] + xh[2] * g[2];
    for (int i = 0; i < 3; ++i) {
      u[i] += a * g[i] + b * xh[i] * xhDotG;
    }
  }
};

} // namespace

void addLocalPart2P(const PeriodicLayer& layer, const SpectralEwaldSettings& settings,
                    const std::vector<double>& sources, const std::vector<double>& forces,
                    const std::vector<double>& targets, std::vector<double>& velocities)
{
  detail::addLocalPart<LocalStokesletKernel>(layer, settings, sources, forces, targets, velocities);
}

} // namespace capsula::ewald
