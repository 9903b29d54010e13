#pragma once
// How an adhering cell moves along the flow, from its centroid at the output times: the
// mean velocity and the pauses of the stop-and-go motion of rolling adhesion (Chang, Tees &
// Hammer, PNAS 97:11262, 2000, classify a cell as free, rolling or firmly adhered by its
// mean velocity and the fraction of time it stands).
//
// Between two consecutive outputs the cell moves at the mean velocity (x_{k+1} - x_k) /
// (t_{k+1} - t_k); an interval in which that is below the threshold counts as paused. The
// resolution is the output interval: a pause shorter than it shows only if it slows the
// interval's mean below the threshold.
#include <vector>

namespace capsula::run {

struct RollingStatistics {
  double observedTime = 0.0;  ///< t_last - t_first, 1/k
  double meanVelocity = 0.0;  ///< (x_last - x_first) / observedTime, a k; 0 with one output
  double pauseFraction = 0.0; ///< paused time / observedTime
  double longestPause = 0.0;  ///< the longest run of paused intervals, 1/k
  int pauses = 0;             ///< runs of consecutive paused intervals
};

/// The statistics of one cell from the output times `times` and its centroids (x, y, z per
/// output); `threshold` is the velocity (a k) below which the cell counts as paused.
RollingStatistics rollingStatistics(const std::vector<double>& times, const std::vector<double>& centroids,
                                    double threshold);

} // namespace capsula::run
