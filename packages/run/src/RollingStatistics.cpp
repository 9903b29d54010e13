#include "capsula/run/RollingStatistics.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>

namespace capsula::run {

namespace core = capsula::core;

RollingStatistics rollingStatistics(const std::vector<double>& times, const std::vector<double>& centroids,
                                    double threshold)
{
  core::require(centroids.size() == 3 * times.size(), "rollingStatistics: ", centroids.size() / 3, " centroids for ",
                times.size(), " times");
  RollingStatistics s;
  if (times.size() < 2) {
    return s;
  }
  s.observedTime = times.back() - times.front();
  s.meanVelocity = (centroids[3 * (times.size() - 1)] - centroids[0]) / s.observedTime;
  double paused = 0.0, current = 0.0;
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const double dt = times[k + 1] - times[k];
    if ((centroids[3 * (k + 1)] - centroids[3 * k]) / dt < threshold) {
      s.pauses += current == 0.0 ? 1 : 0;
      current += dt;
      paused += dt;
      s.longestPause = std::max(s.longestPause, current);
    } else {
      current = 0.0;
    }
  }
  s.pauseFraction = paused / s.observedTime;
  return s;
}

} // namespace capsula::run
