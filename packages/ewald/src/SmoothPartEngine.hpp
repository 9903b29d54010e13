#pragma once
// The smooth part of a spectral Ewald sum in a 2P layer (SpectralEwald2P.hpp), for any kernel
// that is a Stokes singularity: sources with C components are spread with Gaussians onto the grid,
// FFT'd, multiplied by the kernel's screened transform (Kernel::multiply: C components in, 3
// out, (k_x, k_z) != 0), transformed back, given the zero mode (each source component's x-z sum
// convolved in y with the kernel's 1D profile Kernel::zeroModeProfile, then combined by
// Kernel::combineZeroMode), and gathered at the targets.
#include "FftwGrids.hpp"

#include "capsula/ewald/SpectralEwald2P.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <vector>

namespace capsula::ewald::detail {

/// The grid points a Gaussian centred at x reaches along one axis: first index (unwrapped) and
/// the weights e^{-alpha (x_i - x)^2}.
struct AxisStencil {
  int first = 0;
  std::vector<double> weight;
};

inline AxisStencil axisStencil(double x, double origin, double spacing, double radius, double alpha)
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

/// visit(grid index, weight) over the grid points of the normalised Gaussian at x.
template <class Visit>
void forEachGridPoint(const SpectralEwaldSettings& s, const double* x, Visit visit)
{
  constexpr double enginePi = 3.14159265358979323846;
  const double alpha = s.gaussianExponent;
  const AxisStencil sx = axisStencil(x[0], 0.0, s.spacingX, s.supportRadius, alpha);
  const AxisStencil sy = axisStencil(x[1], s.yOrigin, s.spacingY, s.supportRadius, alpha);
  const AxisStencil sz = axisStencil(x[2], 0.0, s.spacingZ, s.supportRadius, alpha);
  const double normalisation = std::pow(alpha / enginePi, 1.5);
  // The wrapped z indices once per point, not once per grid point (an integer division each).
  const std::size_t countZ = sz.weight.size();
  std::vector<int> wrappedZ(countZ);
  for (std::size_t c = 0; c < countZ; ++c) {
    wrappedZ[c] = ((sz.first + static_cast<int>(c)) % s.gridZ + s.gridZ) % s.gridZ;
  }
  for (std::size_t a = 0; a < sx.weight.size(); ++a) {
    const int i = ((sx.first + static_cast<int>(a)) % s.gridX + s.gridX) % s.gridX;
    for (std::size_t b = 0; b < sy.weight.size(); ++b) {
      const int j = sy.first + static_cast<int>(b);
      const double wxy = normalisation * sx.weight[a] * sy.weight[b];
      const std::size_t row = (static_cast<std::size_t>(i) * s.gridY + j) * s.gridZ;
      for (std::size_t c = 0; c < countZ; ++c) {
        visit(row + wrappedZ[c], wxy * sz.weight[c]);
      }
    }
  }
}

/// The points (3 numbers each) in the order of their grid rows (x index, then y index), so that
/// consecutive spreading and gathering touch neighbouring memory.
inline std::vector<std::size_t> gridOrder(const SpectralEwaldSettings& s, const std::vector<double>& points)
{
  const std::size_t count = points.size() / 3;
  std::vector<std::size_t> order(count);
  std::vector<long long> key(count);
  for (std::size_t n = 0; n < count; ++n) {
    order[n] = n;
    const double xFolded = points[3 * n] - s.gridX * s.spacingX * std::floor(points[3 * n] / (s.gridX * s.spacingX));
    const long long i = static_cast<long long>(xFolded / s.spacingX);
    const long long j = static_cast<long long>(std::floor((points[3 * n + 1] - s.yOrigin) / s.spacingY));
    key[n] = i * (s.gridY + 1) + j;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  return order;
}

/// Signed wavenumber index of FFT index i on n points; n / 2 (Nyquist, even n) returns n.
inline int signedIndex(int i, int n)
{
  if (2 * i == n) {
    return n;
  }
  return 2 * i < n ? i : i - n;
}

/// out = Kernel::multiply(k, in) on the half spectrum; the (k_x, k_z) = 0 line (the zero mode,
/// added in y afterwards) and the Nyquist planes (below the tolerance) are set to zero.
template <class Kernel>
void multiplySpectrum(const PeriodicLayer& layer, const SpectralEwaldSettings& s, std::vector<ComplexGrid>& in,
                      ComplexGrid (&out)[3])
{
  constexpr double enginePi = 3.14159265358979323846;
  const int halfZ = s.gridZ / 2 + 1;
  const double periodY = s.gridY * s.spacingY;
  const double scale = 1.0 / (static_cast<double>(s.gridX) * s.gridY * s.gridZ);
  std::complex<double> h[Kernel::sourceComponents], u[3];
  for (int i = 0; i < s.gridX; ++i) {
    const int mi = signedIndex(i, s.gridX);
    for (int j = 0; j < s.gridY; ++j) {
      const int mj = signedIndex(j, s.gridY);
      for (int l = 0; l < halfZ; ++l) {
        const std::size_t index = (static_cast<std::size_t>(i) * s.gridY + j) * halfZ + l;
        const bool nyquist = mi == s.gridX || mj == s.gridY || 2 * l == s.gridZ;
        if (nyquist || (mi == 0 && l == 0)) {
          for (auto& component : out) {
            component[index][0] = component[index][1] = 0.0;
          }
          continue;
        }
        const double k[3] = {2.0 * enginePi * mi / layer.lengthX, 2.0 * enginePi * mj / periodY,
                             2.0 * enginePi * l / layer.lengthZ};
        for (int c = 0; c < Kernel::sourceComponents; ++c) {
          h[c] = scale * std::complex<double>(in[c][index][0], in[c][index][1]);
        }
        Kernel::multiply(k, s.xi, s.eta, h, u);
        for (int c = 0; c < 3; ++c) {
          out[c][index][0] = u[c].real();
          out[c][index][1] = u[c].imag();
        }
      }
    }
  }
}

/// The zero mode on the grid (ZeroMode2P.hpp): the x-z sums rho_c(y_j) of the spread source
/// components, convolved in y with Kernel::zeroModeProfile (the inverse transform of the
/// kernel's (k_x, k_z) = 0 multiplier), combined into the 3 velocity components, divided by the
/// cell area and added to the field on the grid.
template <class Kernel>
void addZeroMode(const PeriodicLayer& layer, const SpectralEwaldSettings& s, const std::vector<RealGrid>& spread,
                 RealGrid (&field)[3])
{
  std::vector<double> kernel(2 * s.gridY - 1);
  for (int d = -(s.gridY - 1); d < s.gridY; ++d) {
    kernel[d + s.gridY - 1] = Kernel::zeroModeProfile(d * s.spacingY, s.xi, s.eta);
  }
  const double weight = s.spacingX * s.spacingY * s.spacingZ / (layer.lengthX * layer.lengthZ);
  std::vector<std::vector<double>> convolved(Kernel::sourceComponents, std::vector<double>(s.gridY, 0.0));
  for (int c = 0; c < Kernel::sourceComponents; ++c) {
    std::vector<double> rho(s.gridY, 0.0);
    for (int i = 0; i < s.gridX; ++i) {
      for (int j = 0; j < s.gridY; ++j) {
        const double* row = spread[c].get() + (static_cast<std::size_t>(i) * s.gridY + j) * s.gridZ;
        for (int l = 0; l < s.gridZ; ++l) {
          rho[j] += row[l];
        }
      }
    }
    for (int j = 0; j < s.gridY; ++j) {
      for (int q = 0; q < s.gridY; ++q) {
        convolved[c][j] += kernel[j - q + s.gridY - 1] * rho[q];
      }
      convolved[c][j] *= weight;
    }
  }
  for (int j = 0; j < s.gridY; ++j) {
    double in[Kernel::sourceComponents], out[3];
    for (int c = 0; c < Kernel::sourceComponents; ++c) {
      in[c] = convolved[c][j];
    }
    Kernel::combineZeroMode(in, out);
    for (int c = 0; c < 3; ++c) {
      for (int i = 0; i < s.gridX; ++i) {
        double* row = field[c].get() + (static_cast<std::size_t>(i) * s.gridY + j) * s.gridZ;
        for (int l = 0; l < s.gridZ; ++l) {
          row[l] += out[c];
        }
      }
    }
  }
}

/// u_t += the smooth part at the targets of the sources' densities (C numbers per source).
template <class Kernel>
void addSmoothPart(const PeriodicLayer& layer, const SpectralEwaldSettings& s, const std::vector<double>& sources,
                   const std::vector<double>& densities, const std::vector<double>& targets,
                   std::vector<double>& velocities)
{
  constexpr int C = Kernel::sourceComponents;
  const std::size_t points = static_cast<std::size_t>(s.gridX) * s.gridY * s.gridZ;
  const std::size_t modes = static_cast<std::size_t>(s.gridX) * s.gridY * (s.gridZ / 2 + 1);
  std::vector<RealGrid> spread;
  std::vector<ComplexGrid> spectrum;
  for (int c = 0; c < C; ++c) {
    spread.push_back(makeRealGrid(points, true));
    spectrum.push_back(makeComplexGrid(modes));
  }
  RealGrid field[3] = {makeRealGrid(points, false), makeRealGrid(points, false), makeRealGrid(points, false)};
  ComplexGrid fieldSpectrum[3];
  for (auto& component : fieldSpectrum) {
    component = makeComplexGrid(modes);
  }
  for (std::size_t n : gridOrder(s, sources)) {
    const double* q = &densities[C * n];
    forEachGridPoint(s, &sources[3 * n], [&](std::size_t index, double weight) {
      for (int c = 0; c < C; ++c) {
        spread[c][index] += weight * q[c];
      }
    });
  }
  // FFTW_ESTIMATE plans do not touch the arrays; an out-of-place r2c keeps its input (the zero
  // mode needs it).
  for (int c = 0; c < C; ++c) {
    fftw_plan forward =
        fftw_plan_dft_r2c_3d(s.gridX, s.gridY, s.gridZ, spread[c].get(), spectrum[c].get(), FFTW_ESTIMATE);
    fftw_execute(forward);
    fftw_destroy_plan(forward);
  }
  multiplySpectrum<Kernel>(layer, s, spectrum, fieldSpectrum);
  for (int c = 0; c < 3; ++c) {
    fftw_plan backward =
        fftw_plan_dft_c2r_3d(s.gridX, s.gridY, s.gridZ, fieldSpectrum[c].get(), field[c].get(), FFTW_ESTIMATE);
    fftw_execute(backward);
    fftw_destroy_plan(backward);
  }
  addZeroMode<Kernel>(layer, s, spread, field);
  const double cellVolume = s.spacingX * s.spacingY * s.spacingZ;
  for (std::size_t t : gridOrder(s, targets)) {
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

} // namespace capsula::ewald::detail
