// The reference Fourier series of the channel Stokeslet (ChannelStokeslet2P.hpp).
#include "capsula/ewald/ChannelStokeslet2P.hpp"

#include "ChannelModes.hpp"

#include "capsula/ewald/LatticeSums2P.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace capsula::ewald {

namespace {

constexpr double channelPi = 3.14159265358979323846;

} // namespace

double channelZeroModeProfile(double y, double h, double height)
{
  return 8.0 * channelPi * std::min(y, h) * (height - std::max(y, h)) / height;
}

double channelSeriesCutoff(double distance, double tolerance)
{
  double ad = std::log(1.0 / tolerance);
  for (int iteration = 0; iteration < 30; ++iteration) {
    ad = std::log(1.0 / tolerance) + 3.0 * std::log(1.0 + ad);
  }
  return ad / distance;
}

void periodicChannelStokeslet2P(const PeriodicLayer& layer, double height, const double x[3], const double x0[3],
                                double G[3][3], double tolerance)
{
  const double y = x[1], h = x0[1];
  if (!(height > 0.0) || !(h > 0.0) || !(h < height) || !(y >= 0.0) || !(y <= height) || y == h) {
    throw std::invalid_argument("ewald: the channel series needs 0 < h < H, 0 <= y <= H and y != h");
  }
  double sum[3][3] = {{0.0}};
  forEachModeWithin(layer, channelSeriesCutoff(std::fabs(y - h), tolerance), true, [&](double kx, double kz) {
    const double a = std::sqrt(kx * kx + kz * kz);
    const double kHat[3] = {kx / a, 0.0, kz / a};
    const double tHat[3] = {-kz / a, 0.0, kx / a};
    detail::ChannelProfile wl, wy;
    detail::channelPlaneProfiles(a, height, h, y, wl, wy);
    double T = 0.0, slope = 0.0;
    detail::channelTransverseProfile(a, height, h, y, T, slope);
    const double theta = kx * (x[0] - x0[0]) + kz * (x[2] - x0[2]);
    const double c = 2.0 * std::cos(theta), s = 2.0 * std::sin(theta);
    for (int j : {0, 2}) {
      for (int i : {0, 2}) {
        sum[i][j] += c * (tHat[j] * T * tHat[i] - kHat[j] * wl.d[1] * kHat[i]); // real
      }
      sum[1][j] -= s * a * kHat[j] * wl.d[0]; // imaginary
    }
    for (int i : {0, 2}) {
      sum[i][1] -= s * a * wy.d[1] * kHat[i]; // imaginary
    }
    sum[1][1] += c * a * a * wy.d[0]; // real
  });
  const double area = layer.lengthX * layer.lengthZ;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      G[i][j] = 8.0 * channelPi * sum[i][j] / area;
    }
  }
  const double mean = channelZeroModeProfile(y, h, height) / area;
  G[0][0] += mean;
  G[2][2] += mean;
}

} // namespace capsula::ewald
