#pragma once
// Norms of flat state vectors, as used for error control and steady-state detection.
// Free functions over plain arrays so they vectorise and never allocate.
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace capsula::timeint {

/// max_i |v_i|.
inline double maxNorm(const double* v, std::size_t n)
{
  double m = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    m = std::max(m, std::abs(v[i]));
  }
  return m;
}

/// sqrt(sum_i v_i^2) (not divided by n).
inline double euclideanNorm(const double* v, std::size_t n)
{
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    s += v[i] * v[i];
  }
  return std::sqrt(s);
}

/// max_i |a_i - b_i|.
inline double maxDifference(const double* a, const double* b, std::size_t n)
{
  double m = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    m = std::max(m, std::abs(a[i] - b[i]));
  }
  return m;
}

/// sqrt(sum_i (a_i - b_i)^2).
inline double euclideanDifference(const double* a, const double* b, std::size_t n)
{
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = a[i] - b[i];
    s += d * d;
  }
  return std::sqrt(s);
}

/// The mixed absolute/relative error norm of Hairer, Norsett & Wanner (II.4.11):
///   sqrt( 1/n sum_i (e_i / sc_i)^2 ),  sc_i = atol + rtol max(|y0_i|, |y1_i|).
/// A step is acceptable when this is <= 1. Zero for n = 0.
inline double scaledRmsNorm(const double* e, const double* y0, const double* y1, std::size_t n, double atol,
                            double rtol)
{
  if (n == 0) {
    return 0.0;
  }
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double scale = atol + rtol * std::max(std::abs(y0[i]), std::abs(y1[i]));
    const double r = e[i] / scale;
    s += r * r;
  }
  return std::sqrt(s / static_cast<double>(n));
}

/// The mixed absolute/relative error norm in the max norm:
///   max_i |e_i| / sc_i,  sc_i = atol + rtol max(|y0_i|, |y1_i|)
/// (acceptable when <= 1): the largest coordinate error measured against the tolerance,
/// as RKF45's |x5 - x4| is, so that no node's error hides in an average.
inline double scaledMaxNorm(const double* e, const double* y0, const double* y1, std::size_t n, double atol,
                            double rtol)
{
  double m = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double scale = atol + rtol * std::max(std::abs(y0[i]), std::abs(y1[i]));
    m = std::max(m, std::abs(e[i]) / scale);
  }
  return m;
}

/// Index of the first non-finite entry, or n if all are finite.
inline std::size_t firstNonFinite(const double* v, std::size_t n)
{
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) {
      return i;
    }
  }
  return n;
}

} // namespace capsula::timeint
