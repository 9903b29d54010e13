// The fast double layer of the channel's stresslet (SpectralEwaldChannelStresslet2P.hpp): the
// channel's groups (ChannelGroups.hpp) over the lower wall's fast double layer.
#include "capsula/ewald/SpectralEwaldChannelStresslet2P.hpp"

#include "ChannelGroups.hpp"

#include "capsula/ewald/SpectralEwaldWallStresslet2P.hpp"

#include <stdexcept>

namespace capsula::ewald {

std::vector<double> spectralEwaldChannelStresslet2P(const PeriodicLayer& layer, double height, double tolerance,
                                                    const std::vector<double>& sources,
                                                    const std::vector<double>& tensors,
                                                    const std::vector<double>& targets)
{
  if (tensors.size() != 3 * sources.size()) {
    throw std::invalid_argument("ewald: sources and targets need 3 numbers per point, tensors 9 per source");
  }
  return detail::channelSum(
      layer, height, tolerance, sources, tensors, 9, targets,
      [&](const std::vector<double>& s, const std::vector<double>& S, const std::vector<double>& points) {
        return spectralEwaldWallStresslet2P(layer, tolerance, s, S, points);
      },
      [](double* S) {
        // s_i s_k S_ik: the entries with one y index (xy, yx, yz, zy) change sign.
        for (int entry : {1, 3, 5, 7}) {
          S[entry] = -S[entry];
        }
      });
}

} // namespace capsula::ewald
