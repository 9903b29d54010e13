// The fast sum of the channel Stokeslet (SpectralEwaldChannel2P.hpp): the channel's groups
// (ChannelGroups.hpp) over the lower wall's fast Stokeslet sum.
#include "capsula/ewald/SpectralEwaldChannel2P.hpp"

#include "ChannelGroups.hpp"

#include "capsula/ewald/SpectralEwaldWall2P.hpp"

#include <stdexcept>

namespace capsula::ewald {

std::vector<double> spectralEwaldChannel2P(const PeriodicLayer& layer, double height, double tolerance,
                                           const std::vector<double>& sources, const std::vector<double>& forces,
                                           const std::vector<double>& targets)
{
  if (forces.size() != sources.size()) {
    throw std::invalid_argument("ewald: sources, forces and targets need 3 numbers per point, one force per source");
  }
  return detail::channelSum(
      layer, height, tolerance, sources, forces, 3, targets,
      [&](const std::vector<double>& s, const std::vector<double>& f, const std::vector<double>& points) {
        return spectralEwaldWall2P(layer, tolerance, s, f, points);
      },
      [](double* force) { force[1] = -force[1]; });
}

} // namespace capsula::ewald
