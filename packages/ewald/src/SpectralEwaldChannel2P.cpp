// The fast sum of the channel Stokeslet (SpectralEwaldChannel2P.hpp): two lower-wall sums, one
// in the reflected frame, each corrected on its far wall by the slab flows of SlabWallFlow.hpp.
#include "capsula/ewald/SpectralEwaldChannel2P.hpp"

#include "FftwGrids.hpp"
#include "SlabFlowGather.hpp"

#include "capsula/ewald/SlabWallFlow.hpp"
#include "capsula/ewald/SpectralEwaldWall2P.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <stdexcept>

namespace capsula::ewald {

namespace {

constexpr double channelFastPi = 3.14159265358979323846;

/// k_c with e^{-k_c d} (1 + k_c d)^2 = tol: the far-wall modes beyond it are below tol.
double farWallCutoff(double gap, double tolerance)
{
  double kd = std::log(1.0 / tolerance);
  for (int iteration = 0; iteration < 30; ++iteration) {
    kd = std::log(1.0 / tolerance) + 2.0 * std::log(1.0 + kd);
  }
  return kd / gap;
}

/// The far wall's velocity (3 components on an Mx x Mz grid, x-major) as Fourier
/// coefficients (1 / (Mx Mz)) sum u e^{-i k.x}, r2c layout Mx x (Mz / 2 + 1) per component.
std::vector<std::complex<double>> farWallSpectrum(const std::vector<double>& onGrid, int Mx, int Mz)
{
  const int half = Mz / 2 + 1;
  std::vector<std::complex<double>> spectrum(3 * static_cast<std::size_t>(Mx) * half);
  const detail::RealGrid real = detail::makeRealGrid(static_cast<std::size_t>(Mx) * Mz, false);
  const detail::ComplexGrid modes = detail::makeComplexGrid(static_cast<std::size_t>(Mx) * half);
  fftw_plan plan = fftw_plan_dft_r2c_2d(Mx, Mz, real.get(), modes.get(), FFTW_ESTIMATE);
  for (int c = 0; c < 3; ++c) {
    for (int p = 0; p < Mx * Mz; ++p) {
      real[p] = onGrid[3 * p + c];
    }
    fftw_execute(plan);
    for (int p = 0; p < Mx * half; ++p) {
      spectrum[3 * p + c] = std::complex<double>(modes[p][0], modes[p][1]) / static_cast<double>(Mx * Mz);
    }
  }
  fftw_destroy_plan(plan);
  return spectrum;
}

/// u_t += the slab flows cancelling the far wall's modes |k| <= k_c (SlabWallFlow.hpp;
/// gathered by SlabFlowGather.hpp), and the mode k = 0 as V y / H.
void addFarWallCorrection(const PeriodicLayer& layer, double height, double kc, double tolerance,
                          const std::vector<std::complex<double>>& spectrum, int Mx, int Mz,
                          const std::vector<double>& targets, std::vector<double>& u)
{
  const int half = Mz / 2 + 1;
  const int mMax = static_cast<int>(std::floor(kc * layer.lengthX / (2.0 * channelFastPi)));
  const int nMax = static_cast<int>(std::floor(kc * layer.lengthZ / (2.0 * channelFastPi)));
  std::vector<SlabMode> modes;
  for (int n = 0; n <= nMax; ++n) {
    for (int m = -mMax; m <= mMax; ++m) {
      const double kx = 2.0 * channelFastPi * m / layer.lengthX;
      const double kz = 2.0 * channelFastPi * n / layer.lengthZ;
      if ((n == 0 && m <= 0) || kx * kx + kz * kz > kc * kc) {
        continue;
      }
      const std::complex<double>* coefficient = &spectrum[3 * (static_cast<std::size_t>((m + Mx) % Mx) * half + n)];
      const std::complex<double> cancel[3] = {-coefficient[0], -coefficient[1], -coefficient[2]};
      modes.push_back(SlabMode{m, n, SlabWallFlow(kx, kz, height, cancel)});
    }
  }
  const double meanX = -spectrum[0].real(), meanZ = -spectrum[2].real();
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    u[t] += meanX * targets[t + 1] / height;
    u[t + 2] += meanZ * targets[t + 1] / height;
  }
  addSlabFlows(layer, height, kc, tolerance, modes, targets, u);
}

/// One group's flow in its own frame (its wall y = 0, the far wall y = H): the lower wall's
/// fast sum at the targets and on a far-wall grid, plus the far-wall correction.
std::vector<double> groupFlow(const PeriodicLayer& layer, double height, double tolerance,
                              const std::vector<double>& sources, const std::vector<double>& forces,
                              const std::vector<double>& targets)
{
  if (sources.empty()) {
    return std::vector<double>(targets.size(), 0.0);
  }
  double highest = 0.0;
  for (std::size_t n = 1; n < sources.size(); n += 3) {
    highest = std::max(highest, sources[n]);
  }
  const double kc = farWallCutoff(height - highest, tolerance);
  // The grid's Nyquist wavenumbers lie beyond k_c, so the modes kept are not aliased by any
  // above the tolerance.
  const int Mx = 2 * static_cast<int>(std::floor(kc * layer.lengthX / (2.0 * channelFastPi))) + 4;
  const int Mz = 2 * static_cast<int>(std::floor(kc * layer.lengthZ / (2.0 * channelFastPi))) + 4;
  std::vector<double> points = targets;
  for (int i = 0; i < Mx; ++i) {
    for (int j = 0; j < Mz; ++j) {
      const double p[3] = {i * layer.lengthX / Mx, height, j * layer.lengthZ / Mz};
      points.insert(points.end(), p, p + 3);
    }
  }
  std::vector<double> u = spectralEwaldWall2P(layer, tolerance, sources, forces, points);
  const std::vector<double> onGrid(u.begin() + static_cast<std::ptrdiff_t>(targets.size()), u.end());
  u.resize(targets.size());
  addFarWallCorrection(layer, height, kc, tolerance, farWallSpectrum(onGrid, Mx, Mz), Mx, Mz, targets, u);
  return u;
}

/// y -> H - y for points, y -> -y for vectors (3 numbers each).
void reflectPoints(std::vector<double>& points, double height)
{
  for (std::size_t n = 1; n < points.size(); n += 3) {
    points[n] = height - points[n];
  }
}
void reflectVectors(std::vector<double>& vectors)
{
  for (std::size_t n = 1; n < vectors.size(); n += 3) {
    vectors[n] = -vectors[n];
  }
}

} // namespace

std::vector<double> spectralEwaldChannel2P(const PeriodicLayer& layer, double height, double tolerance,
                                           const std::vector<double>& sources, const std::vector<double>& forces,
                                           const std::vector<double>& targets)
{
  if (sources.size() % 3 != 0 || forces.size() != sources.size() || targets.size() % 3 != 0) {
    throw std::invalid_argument("ewald: sources, forces and targets need 3 numbers per point, one force per source");
  }
  if (!(height > 0.0) || !(tolerance > 0.0) || !(tolerance < 1.0)) {
    throw std::invalid_argument("ewald: the channel needs a positive height and 0 < tolerance < 1");
  }
  std::vector<double> lowerSources, lowerForces, upperSources, upperForces;
  for (std::size_t n = 0; n < sources.size(); n += 3) {
    const double h = sources[n + 1];
    if (!(h > 0.0) || !(h < height)) {
      throw std::invalid_argument("ewald: channel sources need heights 0 < y < H");
    }
    const bool lower = h <= 0.5 * height;
    auto& s = lower ? lowerSources : upperSources;
    auto& f = lower ? lowerForces : upperForces;
    s.insert(s.end(), &sources[n], &sources[n] + 3);
    f.insert(f.end(), &forces[n], &forces[n] + 3);
  }
  for (std::size_t t = 1; t < targets.size(); t += 3) {
    if (!(targets[t] >= 0.0) || !(targets[t] <= height)) {
      throw std::invalid_argument("ewald: channel targets need heights 0 <= y <= H");
    }
  }
  std::vector<double> u = groupFlow(layer, height, tolerance, lowerSources, lowerForces, targets);
  std::vector<double> reflectedTargets = targets;
  reflectPoints(upperSources, height);
  reflectVectors(upperForces);
  reflectPoints(reflectedTargets, height);
  std::vector<double> upper = groupFlow(layer, height, tolerance, upperSources, upperForces, reflectedTargets);
  reflectVectors(upper);
  for (std::size_t i = 0; i < u.size(); ++i) {
    u[i] += upper[i];
  }
  return u;
}

} // namespace capsula::ewald
