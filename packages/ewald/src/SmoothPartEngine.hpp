#pragma once
// The smooth part of a spectral Ewald sum in a 2P layer (SpectralEwald2P.hpp), for any kernel
// that is a Stokes singularity: sources with C components are spread with Gaussians onto the grid
// (y-levels outermost: index (j N_x + i) N_z + l), FFT'd in x and z on every level, each mode
// (k_x, k_z) != 0 FFT'd in y over its own zero-padded period (yPeriodLevels), multiplied by the
// kernel's screened transform (Kernel::multiply: C components in, 3 out), transformed back,
// given the zero mode (each source component's x-z sum convolved in y with the kernel's 1D
// profile Kernel::zeroModeProfile, then combined by Kernel::combineZeroMode), and gathered at
// the targets.
#include "FftwGrids.hpp"
#include "GaussianGridding.hpp"

#include "capsula/ewald/SpectralEwald2P.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <vector>

namespace capsula::ewald::detail {

/// Signed wavenumber index of FFT index i on n points; n / 2 (Nyquist, even n) returns n.
inline int signedIndex(int i, int n)
{
  if (2 * i == n) {
    return n;
  }
  return 2 * i < n ? i : i - n;
}

/// One FFT length in y: the plans of a zero-padded column of `length` levels, in place.
struct ColumnTransform {
  int length;
  ComplexGrid buffer;
  fftw_plan forward, backward;

  explicit ColumnTransform(int n)
      : length(n),
        buffer(makeComplexGrid(static_cast<std::size_t>(n))),
        forward(fftw_plan_dft_1d(n, buffer.get(), buffer.get(), FFTW_FORWARD, FFTW_ESTIMATE)),
        backward(fftw_plan_dft_1d(n, buffer.get(), buffer.get(), FFTW_BACKWARD, FFTW_ESTIMATE))
  {}
  ~ColumnTransform()
  {
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
  }
  ColumnTransform(const ColumnTransform&) = delete;
  ColumnTransform& operator=(const ColumnTransform&) = delete;
};

/// The field's x-z spectrum on the y-levels, out[c][(j, mode)], from the sources' in[c]: for each
/// mode (k_x, k_z) != 0 below the Nyquist planes, the levels padded with zeros to the mode's
/// y-period M (yPeriodLevels), FFT'd, multiplied by Kernel::multiply(k) (k_y = 2 pi m / (M h)), and
/// transformed back onto the levels. The (k_x, k_z) = 0 line (the zero mode, added in y
/// afterwards) and the Nyquist planes (below the tolerance) are set to zero.
template <class Kernel>
void multiplySpectrum(const PeriodicLayer& layer, const SpectralEwaldSettings& s, std::vector<ComplexGrid>& in,
                      ComplexGrid (&out)[3])
{
  constexpr double enginePi = 3.14159265358979323846;
  constexpr int C = Kernel::sourceComponents;
  const int halfZ = s.gridZ / 2 + 1;
  const std::size_t planeModes = static_cast<std::size_t>(s.gridX) * halfZ;
  std::vector<std::unique_ptr<ColumnTransform>> transforms; // by length, made as needed
  const auto transformOf = [&](int length) -> ColumnTransform& {
    for (auto& t : transforms) {
      if (t->length == length) {
        return *t;
      }
    }
    transforms.push_back(std::make_unique<ColumnTransform>(length));
    return *transforms.back();
  };
  std::vector<std::complex<double>> modes, field;
  std::complex<double> h[C], u[3];
  for (int i = 0; i < s.gridX; ++i) {
    const int mi = signedIndex(i, s.gridX);
    for (int l = 0; l < halfZ; ++l) {
      const std::size_t mode = static_cast<std::size_t>(i) * halfZ + l;
      if (mi == s.gridX || 2 * l == s.gridZ || (mi == 0 && l == 0)) {
        for (auto& component : out) {
          for (int j = 0; j < s.gridY; ++j) {
            component[j * planeModes + mode][0] = component[j * planeModes + mode][1] = 0.0;
          }
        }
        continue;
      }
      const double kx = 2.0 * enginePi * mi / layer.lengthX, kz = 2.0 * enginePi * l / layer.lengthZ;
      ColumnTransform& transform = transformOf(yPeriodLevels(s, std::hypot(kx, kz)));
      const int length = transform.length;
      const double scale = 1.0 / (static_cast<double>(s.gridX) * s.gridZ * length);
      modes.assign(static_cast<std::size_t>(C) * length, 0.0);
      fftw_complex* buffer = transform.buffer.get();
      for (int c = 0; c < C; ++c) { // the C source columns, transformed in y
        for (int j = 0; j < length; ++j) {
          const bool level = j < s.gridY;
          buffer[j][0] = level ? in[c][j * planeModes + mode][0] : 0.0;
          buffer[j][1] = level ? in[c][j * planeModes + mode][1] : 0.0;
        }
        fftw_execute(transform.forward);
        for (int m = 0; m < length; ++m) {
          modes[static_cast<std::size_t>(c) * length + m] = scale * std::complex<double>(buffer[m][0], buffer[m][1]);
        }
      }
      field.assign(static_cast<std::size_t>(3) * length, 0.0);
      for (int m = 0; m < length; ++m) {
        const int mj = signedIndex(m, length);
        if (mj == length) {
          continue; // the y Nyquist mode
        }
        const double k[3] = {kx, 2.0 * enginePi * mj / (length * s.spacingY), kz};
        for (int c = 0; c < C; ++c) {
          h[c] = modes[static_cast<std::size_t>(c) * length + m];
        }
        Kernel::multiply(k, s.xi, s.eta, h, u);
        for (int c = 0; c < 3; ++c) {
          field[static_cast<std::size_t>(c) * length + m] = u[c];
        }
      }
      for (int c = 0; c < 3; ++c) { // back onto the levels
        for (int m = 0; m < length; ++m) {
          buffer[m][0] = field[static_cast<std::size_t>(c) * length + m].real();
          buffer[m][1] = field[static_cast<std::size_t>(c) * length + m].imag();
        }
        fftw_execute(transform.backward);
        for (int j = 0; j < s.gridY; ++j) {
          out[c][j * planeModes + mode][0] = buffer[j][0];
          out[c][j * planeModes + mode][1] = buffer[j][1];
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
    const std::size_t plane = static_cast<std::size_t>(s.gridX) * s.gridZ;
    for (int j = 0; j < s.gridY; ++j) {
      const double* level = spread[c].get() + j * plane;
      for (std::size_t p = 0; p < plane; ++p) {
        rho[j] += level[p];
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
    const std::size_t plane = static_cast<std::size_t>(s.gridX) * s.gridZ;
    for (int c = 0; c < 3; ++c) {
      double* level = field[c].get() + j * plane;
      for (std::size_t p = 0; p < plane; ++p) {
        level[p] += out[c];
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
  std::vector<double*> spreadGrids;
  for (auto& grid : spread) {
    spreadGrids.push_back(grid.get());
  }
  spreadOnGrid(s, sources, densities, C, spreadGrids.data());
  // FFTW_ESTIMATE plans do not touch the arrays; an out-of-place r2c keeps its input (the zero
  // mode needs it). The 2D transforms in x and z run on every y-level (contiguous planes).
  const int n[2] = {s.gridX, s.gridZ};
  const int plane = s.gridX * s.gridZ, planeModes = s.gridX * (s.gridZ / 2 + 1);
  for (int c = 0; c < C; ++c) {
    fftw_plan forward = fftw_plan_many_dft_r2c(2, n, s.gridY, spread[c].get(), nullptr, 1, plane, spectrum[c].get(),
                                               nullptr, 1, planeModes, FFTW_ESTIMATE);
    fftw_execute(forward);
    fftw_destroy_plan(forward);
  }
  multiplySpectrum<Kernel>(layer, s, spectrum, fieldSpectrum);
  for (int c = 0; c < 3; ++c) {
    fftw_plan backward = fftw_plan_many_dft_c2r(2, n, s.gridY, fieldSpectrum[c].get(), nullptr, 1, planeModes,
                                                field[c].get(), nullptr, 1, plane, FFTW_ESTIMATE);
    fftw_execute(backward);
    fftw_destroy_plan(backward);
  }
  addZeroMode<Kernel>(layer, s, spread, field);
  const double* fieldGrids[3] = {field[0].get(), field[1].get(), field[2].get()};
  gatherFromGrid(s, targets, fieldGrids, s.spacingX * s.spacingY * s.spacingZ, velocities);
}

} // namespace capsula::ewald::detail
