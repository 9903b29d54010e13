// The reference Fourier series of the channel's stress (ChannelStresslet2P.hpp).
#include "capsula/ewald/ChannelStresslet2P.hpp"

#include "ChannelModes.hpp"

#include "capsula/ewald/ChannelStokeslet2P.hpp"
#include "capsula/ewald/LatticeSums2P.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

namespace capsula::ewald {

namespace {

constexpr double channelStressPi = 3.14159265358979323846;
using Complex = std::complex<double>;

/// One mode's velocity u[i][j], its y-derivative and the pressure p[j] for unit forces e_j
/// (ChannelStokeslet2P.hpp, ChannelStresslet2P.hpp).
struct ModeFlow {
  Complex u[3][3], slope[3][3], p[3];
};

ModeFlow modeFlow(double kx, double kz, double height, double h, double y)
{
  const double a = std::sqrt(kx * kx + kz * kz);
  const double kHat[3] = {kx / a, 0.0, kz / a};
  const double tHat[3] = {-kz / a, 0.0, kx / a};
  detail::ChannelProfile wl, wy;
  detail::channelPlaneProfiles(a, height, h, y, wl, wy);
  double T = 0.0, TSlope = 0.0;
  detail::channelTransverseProfile(a, height, h, y, T, TSlope);
  const Complex i(0.0, 1.0);
  ModeFlow f;
  for (int j : {0, 2}) { // g_l = kHat_j, g_t = tHat_j
    for (int m : {0, 2}) {
      f.u[m][j] = -kHat[j] * wl.d[1] * kHat[m] + tHat[j] * T * tHat[m];
      f.slope[m][j] = -kHat[j] * wl.d[2] * kHat[m] + tHat[j] * TSlope * tHat[m];
    }
    f.u[1][j] = i * a * kHat[j] * wl.d[0];
    f.slope[1][j] = i * a * kHat[j] * wl.d[1];
    f.p[j] = i * kHat[j] * (wl.d[3] - a * a * wl.d[1]) / a;
  }
  for (int m : {0, 2}) { // g_y = 1
    f.u[m][1] = i * a * wy.d[1] * kHat[m];
    f.slope[m][1] = i * a * wy.d[2] * kHat[m];
  }
  f.u[1][1] = a * a * wy.d[0];
  f.slope[1][1] = a * a * wy.d[1];
  f.p[1] = wy.d[3] - a * a * wy.d[1];
  return f;
}

} // namespace

void periodicChannelStresslet2P(const PeriodicLayer& layer, double height, const double x[3], const double x0[3],
                                double T[3][3][3], double tolerance)
{
  const double y = x[1], h = x0[1];
  if (!(height > 0.0) || !(h > 0.0) || !(h < height) || !(y >= 0.0) || !(y <= height) || y == h) {
    throw std::invalid_argument("ewald: the channel series needs 0 < h < H, 0 <= y <= H and y != h");
  }
  double sum[3][3][3] = {};
  forEachModeWithin(layer, channelSeriesCutoff(std::fabs(y - h), tolerance), true, [&](double kx, double kz) {
    const ModeFlow f = modeFlow(kx, kz, height, h, y);
    const Complex ik[3] = {Complex(0.0, kx), 0.0, Complex(0.0, kz)};
    const auto gradient = [&](int m, int j, int k) { return k == 1 ? f.slope[m][j] : ik[k] * f.u[m][j]; };
    const Complex phase = 2.0 * std::polar(1.0, kx * (x[0] - x0[0]) + kz * (x[2] - x0[2]));
    for (int m = 0; m < 3; ++m) {
      for (int j = 0; j < 3; ++j) {
        for (int k = 0; k < 3; ++k) {
          const Complex t = (m == k ? -f.p[j] : 0.0) + gradient(m, j, k) + gradient(k, j, m);
          sum[m][j][k] += (t * phase).real();
        }
      }
    }
  });
  const double area = layer.lengthX * layer.lengthZ;
  const double scale = 8.0 * channelStressPi / area;
  for (int m = 0; m < 3; ++m) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        T[m][j][k] = scale * sum[m][j][k];
      }
    }
  }
  const double shear = scale * (y < h ? (height - h) / height : -h / height);
  const double pressure = scale * ((y > h ? 1.0 : 0.0) - (height - h) / height);
  for (int j : {0, 2}) {
    T[j][j][1] += shear;
    T[1][j][j] += shear;
  }
  for (int m = 0; m < 3; ++m) {
    T[m][1][m] -= pressure;
  }
}

} // namespace capsula::ewald
