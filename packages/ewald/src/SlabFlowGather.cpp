// The gathered sum of the channel's slab flows (SlabFlowGather.hpp).
#include "SlabFlowGather.hpp"

#include "FftwGrids.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>

namespace capsula::ewald {

namespace {

constexpr double gatherPi = 3.14159265358979323846;

/// Ny: the first n with I_n(z) e^{-z} < tol / 100, plus 2 (header comment), at least 4.
int chebyshevLevels(double z, double tolerance)
{
  int n = 1;
  while (n < 200 && std::cyl_bessel_i(static_cast<double>(n), z) * std::exp(-z) >= 0.01 * tolerance) {
    ++n;
  }
  return std::max(n + 2, 4);
}

/// The Chebyshev-Lobatto levels of [0, H] and their barycentric weights.
void chebyshevLevels(int count, double height, std::vector<double>& levels, std::vector<double>& weights)
{
  levels.resize(count);
  weights.resize(count);
  for (int q = 0; q < count; ++q) {
    levels[q] = 0.5 * height * (1.0 - std::cos(gatherPi * q / (count - 1)));
    weights[q] = (q % 2 == 0 ? 1.0 : -1.0) * (q == 0 || q == count - 1 ? 0.5 : 1.0);
  }
}

/// The barycentric interpolation weights l_q(y) (exact at a level).
void interpolationWeights(double y, const std::vector<double>& levels, const std::vector<double>& weights,
                          std::vector<double>& l)
{
  const int count = static_cast<int>(levels.size());
  l.assign(count, 0.0);
  double sum = 0.0;
  for (int q = 0; q < count; ++q) {
    if (y == levels[q]) {
      l.assign(count, 0.0);
      l[q] = 1.0;
      return;
    }
    l[q] = weights[q] / (y - levels[q]);
    sum += l[q];
  }
  for (double& w : l) {
    w /= sum;
  }
}

/// The window's P weights along one axis and the P grid indices (wrapped) nearest x.
void windowWeights(double x, double spacing, int gridSize, int P, double alpha, std::vector<double>& w,
                   std::vector<int>& index)
{
  w.resize(P);
  index.resize(P);
  const int first = static_cast<int>(std::floor(x / spacing)) - P / 2 + 1;
  for (int p = 0; p < P; ++p) {
    const int j = first + p;
    const double r = x - j * spacing;
    w[p] = std::exp(-alpha * r * r);
    index[p] = ((j % gridSize) + gridSize) % gridSize;
  }
}

} // namespace

void addSlabFlows(const PeriodicLayer& layer, double height, double kc, double tolerance,
                  const std::vector<SlabMode>& modes, const std::vector<double>& targets, std::vector<double>& u)
{
  if (modes.empty() || targets.empty()) {
    return;
  }
  const double logInverse = std::log(1.0 / tolerance);
  const double alpha = 2.0 * kc * kc / logInverse;
  int P = static_cast<int>(std::ceil(3.0 * logInverse / gatherPi)) + 2;
  P += P % 2;
  const double h = gatherPi / (2.0 * kc);
  int mMax = 0, nMax = 0;
  for (const SlabMode& mode : modes) {
    mMax = std::max(mMax, std::abs(mode.m));
    nMax = std::max(nMax, mode.n);
  }
  // Grids of spacing <= h (FFTW's fast sizes), large enough for P points and the modes' span.
  const auto gridSize = [&](double length, int indexMax) {
    return detail::fastFftSize(std::max({static_cast<int>(std::ceil(length / h)), P, 2 * indexMax + 2}));
  };
  const int Gx = gridSize(layer.lengthX, mMax), Gz = gridSize(layer.lengthZ, nMax);
  const int half = Gz / 2 + 1;
  const double hx = layer.lengthX / Gx, hz = layer.lengthZ / Gz;
  std::vector<double> levels, baryWeights;
  chebyshevLevels(chebyshevLevels(0.5 * kc * height, tolerance), height, levels, baryWeights);
  const int Ny = static_cast<int>(levels.size());
  const std::size_t plane = static_cast<std::size_t>(Gx) * Gz;
  // Per grid node the 3 Ny values (level-major, then component) side by side: a target reads
  // P^2 contiguous blocks.
  const std::size_t values = 3 * static_cast<std::size_t>(Ny);
  std::vector<double> grids(values * plane);
  const detail::ComplexGrid spectrum = detail::makeComplexGrid(static_cast<std::size_t>(Gx) * half);
  const detail::RealGrid real = detail::makeRealGrid(plane, false);
  fftw_plan plan = fftw_plan_dft_c2r_2d(Gx, Gz, spectrum.get(), real.get(), FFTW_ESTIMATE);
  std::vector<double> deconvolution(modes.size());
  for (std::size_t k = 0; k < modes.size(); ++k) {
    const double kx = 2.0 * gatherPi * modes[k].m / layer.lengthX, kz = 2.0 * gatherPi * modes[k].n / layer.lengthZ;
    deconvolution[k] = alpha / gatherPi * std::exp((kx * kx + kz * kz) / (4.0 * alpha));
  }
  for (int q = 0; q < Ny; ++q) {
    std::vector<std::complex<double>> profiles(3 * modes.size());
    for (std::size_t k = 0; k < modes.size(); ++k) {
      modes[k].flow.velocity(levels[q], &profiles[3 * k]);
    }
    for (int c = 0; c < 3; ++c) {
      std::fill(&spectrum[0][0], &spectrum[0][0] + 2 * Gx * half, 0.0);
      for (std::size_t k = 0; k < modes.size(); ++k) {
        const std::complex<double> g = profiles[3 * k + c] * deconvolution[k];
        const int row = (modes[k].m + Gx) % Gx;
        spectrum[row * half + modes[k].n][0] += g.real();
        spectrum[row * half + modes[k].n][1] += g.imag();
        if (modes[k].n == 0) { // the column n = 0 holds both k and -k (Hermitian)
          const int mirror = (Gx - modes[k].m) % Gx;
          spectrum[mirror * half][0] += g.real();
          spectrum[mirror * half][1] -= g.imag();
        }
      }
      fftw_execute(plan);
      for (std::size_t node = 0; node < plane; ++node) {
        grids[node * values + 3 * q + c] = real[node];
      }
    }
  }
  fftw_destroy_plan(plan);
  std::vector<double> l, wx, wz, gathered(values);
  std::vector<int> ix, iz;
  for (std::size_t t = 0; t < targets.size(); t += 3) {
    interpolationWeights(targets[t + 1], levels, baryWeights, l);
    windowWeights(targets[t], hx, Gx, P, alpha, wx, ix);
    windowWeights(targets[t + 2], hz, Gz, P, alpha, wz, iz);
    std::fill(gathered.begin(), gathered.end(), 0.0);
    for (int i = 0; i < P; ++i) {
      for (int j = 0; j < P; ++j) {
        const double w = wx[i] * wz[j];
        const double* node = &grids[(static_cast<std::size_t>(ix[i]) * Gz + iz[j]) * values];
        for (std::size_t r = 0; r < values; ++r) {
          gathered[r] += w * node[r];
        }
      }
    }
    for (int q = 0; q < Ny; ++q) {
      for (int c = 0; c < 3; ++c) {
        u[t + c] += hx * hz * l[q] * gathered[3 * q + c];
      }
    }
  }
}

} // namespace capsula::ewald
