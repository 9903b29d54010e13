// The channel's sums from one wall's (ChannelGroups.hpp): the far-wall spectrum and the slab
// correction of each group, and the split into the lower and the upper group.
#include "ChannelGroups.hpp"

#include "FftwGrids.hpp"
#include "SlabFlowGather.hpp"

#include "capsula/ewald/SlabWallFlow.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace capsula::ewald::detail {

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
  const RealGrid real = makeRealGrid(static_cast<std::size_t>(Mx) * Mz, false);
  const ComplexGrid modes = makeComplexGrid(static_cast<std::size_t>(Mx) * half);
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
/// gathered by SlabFlowGather.hpp), and the mode k = 0 as V y / H (V_y is the outflow of the
/// group's sources: zero for forces, the sum of tr S for stresslets).
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
  const double mean[3] = {-spectrum[0].real(), -spectrum[1].real(), -spectrum[2].real()};
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    for (int i = 0; i < 3; ++i) {
      u[t + i] += mean[i] * targets[t + 1] / height;
    }
  }
  addSlabFlows(layer, height, kc, tolerance, modes, targets, u);
}

/// One group's flow in its own frame (its wall y = 0, the far wall y = H): the wall's fast
/// sum at the targets and on a far-wall grid, plus the far-wall correction.
std::vector<double> groupFlow(const PeriodicLayer& layer, double height, double tolerance,
                              const std::vector<double>& sources, const std::vector<double>& densities,
                              const std::vector<double>& targets, const WallSum& wallSum)
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
  std::vector<double> u = wallSum(sources, densities, points);
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

std::vector<double> channelSum(const PeriodicLayer& layer, double height, double tolerance,
                               const std::vector<double>& sources, const std::vector<double>& densities, int components,
                               const std::vector<double>& targets, const WallSum& wallSum,
                               const DensityReflection& reflectDensity)
{
  if (sources.size() % 3 != 0 || densities.size() != components * (sources.size() / 3) || targets.size() % 3 != 0) {
    throw std::invalid_argument("ewald: sources and targets need 3 numbers per point, and each source its density");
  }
  if (!(height > 0.0) || !(tolerance > 0.0) || !(tolerance < 1.0)) {
    throw std::invalid_argument("ewald: the channel needs a positive height and 0 < tolerance < 1");
  }
  std::vector<double> lowerSources, lowerDensities, upperSources, upperDensities;
  for (std::size_t n = 0; 3 * n < sources.size(); ++n) {
    const double h = sources[3 * n + 1];
    if (!(h > 0.0) || !(h < height)) {
      throw std::invalid_argument("ewald: channel sources need heights 0 < y < H");
    }
    const bool lower = h <= 0.5 * height;
    auto& s = lower ? lowerSources : upperSources;
    auto& d = lower ? lowerDensities : upperDensities;
    s.insert(s.end(), &sources[3 * n], &sources[3 * n] + 3);
    const double* density = &densities[components * n];
    d.insert(d.end(), density, density + components);
    if (!lower) {
      reflectDensity(&d[d.size() - components]);
    }
  }
  for (std::size_t t = 1; t < targets.size(); t += 3) {
    if (!(targets[t] >= 0.0) || !(targets[t] <= height)) {
      throw std::invalid_argument("ewald: channel targets need heights 0 <= y <= H");
    }
  }
  std::vector<double> u = groupFlow(layer, height, tolerance, lowerSources, lowerDensities, targets, wallSum);
  std::vector<double> reflectedTargets = targets;
  reflectPoints(upperSources, height);
  reflectPoints(reflectedTargets, height);
  std::vector<double> upper =
      groupFlow(layer, height, tolerance, upperSources, upperDensities, reflectedTargets, wallSum);
  reflectVectors(upper);
  for (std::size_t i = 0; i < u.size(); ++i) {
    u[i] += upper[i];
  }
  return u;
}

} // namespace capsula::ewald::detail
