#include "capsula/suspension/HeightDistribution.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>

namespace capsula::suspension {

HeightDistribution heightDistribution(const std::vector<double>& centroidHeights, const domain::Domain& domain,
                                      int numBins)
{
  core::require<core::InputError>(domain.hasUpperWall(), "A wall-normal distribution needs a channel, not ",
                                  domain.describe(), ".");
  core::require<core::InputError>(!centroidHeights.empty() && numBins >= 1,
                                  "A wall-normal distribution needs heights and at least one bin.");
  const double height = domain.channelHeight();
  const double width = height / numBins;
  HeightDistribution distribution;
  for (int k = 0; k <= numBins; ++k) {
    distribution.heights.push_back(height * k / numBins);
  }
  distribution.density.assign(static_cast<std::size_t>(numBins), 0.0);
  for (double y : centroidHeights) {
    core::require<core::InputError>(y > 0.0 && y < height, "A centroid at y = ", y,
                                    " lies outside the channel 0 < y < ", height, ".");
    const int bin = std::min(numBins - 1, static_cast<int>(y / width));
    distribution.density[static_cast<std::size_t>(bin)] += 1.0;
  }
  for (double& d : distribution.density) {
    d /= static_cast<double>(centroidHeights.size()) * width;
  }
  return distribution;
}

} // namespace capsula::suspension
