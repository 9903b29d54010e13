// The smooth part of the spectral Ewald sum (SpectralEwald2P.hpp): Gaussian spreading onto the
// grid, FFT, the screened Stokeslet's transform, inverse FFT, the zero mode in y, gathering.
#include "capsula/ewald/SpectralEwald2P.hpp"
#include "capsula/ewald/ZeroMode2P.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <memory>

namespace capsula::ewald {

namespace {

constexpr double smoothPi = 3.14159265358979323846;

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};
using RealGrid = std::unique_ptr<double[], FftwFree>;
using ComplexGrid = std::unique_ptr<fftw_complex[], FftwFree>;

RealGrid makeRealGrid(std::size_t size)
{
  RealGrid grid(static_cast<double*>(fftw_malloc(sizeof(double) * size)));
  std::fill(grid.get(), grid.get() + size, 0.0);
  return grid;
}

/// The grid points a Gaussian centred at x reaches along one axis, with their weights
/// e^{-alpha (x_i - x)^2}: first index (unwrapped) and the weights.
struct AxisStencil {
  int first = 0;
  std::vector<double> weight;
};

AxisStencil axisStencil(double x, double origin, double spacing, double radius, double alpha)
{
  AxisStencil s;
  s.first = static_cast<int>(std::ceil((x - radius - origin) / spacing));
  const int last = static_cast<int>(std::floor((x + radius - origin) / spacing));
  for (int i = s.first; i <= last; ++i) {
    const double d = origin + i * spacing - x;
    s.weight.push_back(std::exp(-alpha * d * d));
  }
  return s;
}

/// The three stencils of a point; index (i, j, k) of the grid and its weight are visited.
template <class Visit>
void forEachGridPoint(const SpectralEwaldSettings& s, const double* x, Visit visit)
{
  const double alpha = s.gaussianExponent;
  const AxisStencil sx = axisStencil(x[0], 0.0, s.spacingX, s.supportRadius, alpha);
  const AxisStencil sy = axisStencil(x[1], s.yOrigin, s.spacingY, s.supportRadius, alpha);
  const AxisStencil sz = axisStencil(x[2], 0.0, s.spacingZ, s.supportRadius, alpha);
  const double normalisation = std::pow(alpha / smoothPi, 1.5);
  for (std::size_t a = 0; a < sx.weight.size(); ++a) {
    const int i = ((sx.first + static_cast<int>(a)) % s.gridX + s.gridX) % s.gridX;
    for (std::size_t b = 0; b < sy.weight.size(); ++b) {
      const int j = sy.first + static_cast<int>(b);
      const double wxy = normalisation * sx.weight[a] * sy.weight[b];
      const std::size_t row = (static_cast<std::size_t>(i) * s.gridY + j) * s.gridZ;
      for (std::size_t c = 0; c < sz.weight.size(); ++c) {
        const int k = ((sz.first + static_cast<int>(c)) % s.gridZ + s.gridZ) % s.gridZ;
        visit(row + k, wxy * sz.weight[c]);
      }
    }
  }
}

/// Signed wavenumber index of FFT index i on n points; n/2 (Nyquist, even n) returns n.
int signedIndex(int i, int n)
{
  if (2 * i == n) {
    return n;
  }
  return 2 * i < n ? i : i - n;
}

/// hat u = G^F_eta(k) hat H on the half spectrum, the (k_x, k_z) = 0 line and the Nyquist planes
/// set to zero (the zero mode is added in y afterwards; Nyquist modes are below the tolerance).
void multiplyByScreenedStokeslet(const PeriodicLayer& layer, const SpectralEwaldSettings& s, ComplexGrid (&spectrum)[3])
{
  const int halfZ = s.gridZ / 2 + 1;
  const double periodY = s.gridY * s.spacingY;
  const double scale = 8.0 * smoothPi / (static_cast<double>(s.gridX) * s.gridY * s.gridZ);
  const double damping = (1.0 - s.eta) / (4.0 * s.xi * s.xi);
  for (int i = 0; i < s.gridX; ++i) {
    const int mi = signedIndex(i, s.gridX);
    for (int j = 0; j < s.gridY; ++j) {
      const int mj = signedIndex(j, s.gridY);
      for (int l = 0; l < halfZ; ++l) {
        const std::size_t index = (static_cast<std::size_t>(i) * s.gridY + j) * halfZ + l;
        const bool nyquist = mi == s.gridX || mj == s.gridY || 2 * l == s.gridZ;
        if (nyquist || (mi == 0 && l == 0)) {
          for (auto& component : spectrum) {
            component[index][0] = component[index][1] = 0.0;
          }
          continue;
        }
        const double k[3] = {2.0 * smoothPi * mi / layer.lengthX, 2.0 * smoothPi * mj / periodY,
                             2.0 * smoothPi * l / layer.lengthZ};
        const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
        const double factor = scale * (1.0 + k2 / (4.0 * s.xi * s.xi)) * std::exp(-damping * k2) / (k2 * k2);
        std::complex<double> h[3], u[3];
        for (int c = 0; c < 3; ++c) {
          h[c] = {spectrum[c][index][0], spectrum[c][index][1]};
        }
        const std::complex<double> kDotH = k[0] * h[0] + k[1] * h[1] + k[2] * h[2];
        for (int c = 0; c < 3; ++c) {
          u[c] = factor * (k2 * h[c] - k[c] * kDotH);
          spectrum[c][index][0] = u[c].real();
          spectrum[c][index][1] = u[c].imag();
        }
      }
    }
  }
}

/// The zero mode (ZeroMode2P.hpp) on the grid: the x-z sums rho(y_j) of the spread parallel
/// forces, convolved in y with K(y) = h_{xi'}(y) + eta/(1-eta) 2 sqrt(pi)/xi' e^{-xi'^2 y^2},
/// xi' = xi / sqrt(1 - eta) (the inverse transform of 8 pi (1+k^2/4xi^2) e^{-(1-eta)k^2/4xi^2}/k^2),
/// divided by the cell area and added to the parallel components of the field on the grid.
void addZeroMode(const PeriodicLayer& layer, const SpectralEwaldSettings& s, const RealGrid (&spread)[3],
                 RealGrid (&field)[3])
{
  const double xiPrime = s.xi / std::sqrt(1.0 - s.eta);
  const double gaussianWeight = s.eta / (1.0 - s.eta) * 2.0 * std::sqrt(smoothPi) / xiPrime;
  std::vector<double> kernel(2 * s.gridY - 1);
  for (int d = -(s.gridY - 1); d < s.gridY; ++d) {
    const double y = d * s.spacingY;
    kernel[d + s.gridY - 1] = smoothZeroModeProfile(y, xiPrime) + gaussianWeight * std::exp(-xiPrime * xiPrime * y * y);
  }
  const double area = layer.lengthX * layer.lengthZ;
  for (int c : {0, 2}) {
    std::vector<double> rho(s.gridY, 0.0);
    for (int i = 0; i < s.gridX; ++i) {
      for (int j = 0; j < s.gridY; ++j) {
        const double* row = spread[c].get() + (static_cast<std::size_t>(i) * s.gridY + j) * s.gridZ;
        for (int l = 0; l < s.gridZ; ++l) {
          rho[j] += row[l];
        }
      }
    }
    std::vector<double> profile(s.gridY, 0.0);
    for (int j = 0; j < s.gridY; ++j) {
      for (int q = 0; q < s.gridY; ++q) {
        profile[j] += kernel[j - q + s.gridY - 1] * rho[q];
      }
      profile[j] *= s.spacingX * s.spacingY * s.spacingZ / area;
    }
    for (int i = 0; i < s.gridX; ++i) {
      for (int j = 0; j < s.gridY; ++j) {
        double* row = field[c].get() + (static_cast<std::size_t>(i) * s.gridY + j) * s.gridZ;
        for (int l = 0; l < s.gridZ; ++l) {
          row[l] += profile[j];
        }
      }
    }
  }
}

} // namespace

void addSmoothPart2P(const PeriodicLayer& layer, const SpectralEwaldSettings& s, const std::vector<double>& sources,
                     const std::vector<double>& forces, const std::vector<double>& targets,
                     std::vector<double>& velocities)
{
  const std::size_t points = static_cast<std::size_t>(s.gridX) * s.gridY * s.gridZ;
  const std::size_t modes = static_cast<std::size_t>(s.gridX) * s.gridY * (s.gridZ / 2 + 1);
  RealGrid spread[3] = {makeRealGrid(points), makeRealGrid(points), makeRealGrid(points)};
  RealGrid field[3] = {makeRealGrid(points), makeRealGrid(points), makeRealGrid(points)};
  ComplexGrid spectrum[3];
  for (auto& component : spectrum) {
    component.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * modes)));
  }
  const int sourceCount = static_cast<int>(sources.size() / 3);
  for (int n = 0; n < sourceCount; ++n) {
    const double* g = &forces[3 * n];
    forEachGridPoint(s, &sources[3 * n], [&](std::size_t index, double weight) {
      for (int c = 0; c < 3; ++c) {
        spread[c][index] += weight * g[c];
      }
    });
  }
  // Plans are made before the data are needed (FFTW_ESTIMATE does not touch the arrays).
  for (int c = 0; c < 3; ++c) {
    fftw_plan forward =
        fftw_plan_dft_r2c_3d(s.gridX, s.gridY, s.gridZ, spread[c].get(), spectrum[c].get(), FFTW_ESTIMATE);
    fftw_execute(forward);
    fftw_destroy_plan(forward);
  }
  multiplyByScreenedStokeslet(layer, s, spectrum);
  for (int c = 0; c < 3; ++c) {
    fftw_plan backward =
        fftw_plan_dft_c2r_3d(s.gridX, s.gridY, s.gridZ, spectrum[c].get(), field[c].get(), FFTW_ESTIMATE);
    fftw_execute(backward);
    fftw_destroy_plan(backward);
  }
  addZeroMode(layer, s, spread, field);
  const double cellVolume = s.spacingX * s.spacingY * s.spacingZ;
  const int targetCount = static_cast<int>(targets.size() / 3);
  for (int t = 0; t < targetCount; ++t) {
    double u[3] = {0.0, 0.0, 0.0};
    forEachGridPoint(s, &targets[3 * t], [&](std::size_t index, double weight) {
      for (int c = 0; c < 3; ++c) {
        u[c] += weight * field[c][index];
      }
    });
    for (int c = 0; c < 3; ++c) {
      velocities[3 * t + c] += cellVolume * u[c];
    }
  }
}

} // namespace capsula::ewald
