#pragma once
// The wall-normal distribution of one cell type: the probability density of its cells'
// centroid heights over the channel 0 < y < H, as a histogram of equal bins (margination: the
// platelets' density piles up near the walls, the red cells' in the core).
#include <capsula/domain/Domain.hpp>

#include <vector>

namespace capsula::suspension {

struct HeightDistribution {
  std::vector<double> heights; ///< the bin boundaries 0 = y_0 < ... < y_n = H
  std::vector<double> density; ///< count in the bin / (number of cells * bin width): integrates to 1
};

/// The distribution of the heights `centroidHeights` in `numBins` bins across the channel of
/// `domain`. A height outside (0, H) is an error (a cell through a wall). Throws
/// core::InputError without a channel, without heights or with numBins < 1.
HeightDistribution heightDistribution(const std::vector<double>& centroidHeights, const domain::Domain& domain,
                                      int numBins);

} // namespace capsula::suspension
