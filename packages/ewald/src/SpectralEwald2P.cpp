#include "capsula/ewald/SpectralEwald2P.hpp"

#include <algorithm>
#include <stdexcept>

namespace capsula::ewald {

SpectralEwaldSettings spectralEwaldSettingsFor(const PeriodicLayer& layer, double tolerance,
                                               const std::vector<double>& sources, const std::vector<double>& targets,
                                               double xi)
{
  if (sources.empty() || targets.empty()) {
    throw std::invalid_argument("ewald: spectral Ewald settings need sources and targets");
  }
  double yMin = sources[1], yMax = sources[1];
  for (const auto* points : {&sources, &targets}) {
    for (std::size_t n = 1; n < points->size(); n += 3) {
      yMin = std::min(yMin, (*points)[n]);
      yMax = std::max(yMax, (*points)[n]);
    }
  }
  return spectralEwaldSettings(layer, tolerance, yMin, yMax, static_cast<int>(sources.size() / 3), xi);
}

std::vector<double> spectralEwald2P(const PeriodicLayer& layer, double tolerance, const std::vector<double>& sources,
                                    const std::vector<double>& forces, const std::vector<double>& targets, double xi)
{
  if (sources.size() % 3 != 0 || forces.size() != sources.size() || targets.size() % 3 != 0) {
    throw std::invalid_argument("ewald: sources, forces and targets need 3 numbers per point, one force per source");
  }
  std::vector<double> velocities(targets.size(), 0.0);
  if (sources.empty() || targets.empty()) {
    return velocities;
  }
  const SpectralEwaldSettings settings = spectralEwaldSettingsFor(layer, tolerance, sources, targets, xi);
  addLocalPart2P(layer, settings, sources, forces, targets, velocities);
  addSmoothPart2P(layer, settings, sources, forces, targets, velocities);
  return velocities;
}

} // namespace capsula::ewald
