#include "capsula/scene/CubicSpline.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::scene {

namespace core = capsula::core;

namespace {

// Solves a tridiagonal system in place (Thomas algorithm; the spline systems are
// diagonally dominant apart from the not-a-knot rows, handled by the caller's form).
void solveTridiagonal(std::vector<double> lower, std::vector<double> diagonal,
                      std::vector<double> upper, std::vector<double>& rhs)
{
  const std::size_t n = diagonal.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double m = lower[i] / diagonal[i - 1];
    diagonal[i] -= m * upper[i - 1];
    rhs[i] -= m * rhs[i - 1];
  }
  rhs[n - 1] /= diagonal[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) {
    rhs[i] = (rhs[i] - upper[i] * rhs[i + 1]) / diagonal[i];
  }
}

} // namespace

CubicSpline::CubicSpline(std::vector<double> times, std::vector<double> values)
    : times_(std::move(times)), values_(std::move(values))
{
  const std::size_t n = times_.size();
  core::require<core::InputError>(n >= 1 && values_.size() == n, "CubicSpline: ", n,
                                  " times and ", values_.size(),
                                  " values; give at least one sample and as many values as times.");
  for (std::size_t k = 0; k < n; ++k) {
    core::require<core::InputError>(std::isfinite(times_[k]) && std::isfinite(values_[k]),
                                    "CubicSpline: sample ", k, " is not finite.");
    core::require<core::InputError>(k == 0 || times_[k] > times_[k - 1],
                                    "CubicSpline: times must increase strictly, but t[", k,
                                    "] = ", times_[k], " follows ", times_[k - 1], ".");
  }
  slopes_.assign(n, 0.0);
  if (n == 1) {
    return;
  }
  std::vector<double> h(n - 1), delta(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = times_[k + 1] - times_[k];
    delta[k] = (values_[k + 1] - values_[k]) / h[k];
  }
  if (n == 2) {
    slopes_[0] = slopes_[1] = delta[0];
    return;
  }
  if (n == 3) {
    // The interpolating parabola: its slopes at the three samples.
    const double c = (delta[1] - delta[0]) / (h[0] + h[1]);
    slopes_[0] = delta[0] - c * h[0];
    slopes_[1] = delta[0] + c * h[0];
    slopes_[2] = delta[1] + c * h[1];
    return;
  }
  // C2 continuity at the interior samples, in the slopes s_k (de Boor, A Practical Guide
  // to Splines, ch. IV):  h_k s_{k-1} + 2 (h_{k-1} + h_k) s_k + h_{k-1} s_{k+1}
  //                       = 3 (h_k delta_{k-1} + h_{k-1} delta_k).
  // Not-a-knot rows (third derivative continuous at t_1 and t_{n-2}), de Boor's form.
  std::vector<double> lower(n, 0.0), diagonal(n, 0.0), upper(n, 0.0), rhs(n, 0.0);
  diagonal[0] = h[1];
  upper[0] = h[0] + h[1];
  rhs[0] = ((h[0] + 2.0 * upper[0]) * h[1] * delta[0] + h[0] * h[0] * delta[1]) / upper[0];
  for (std::size_t k = 1; k + 1 < n; ++k) {
    lower[k] = h[k];
    diagonal[k] = 2.0 * (h[k - 1] + h[k]);
    upper[k] = h[k - 1];
    rhs[k] = 3.0 * (h[k] * delta[k - 1] + h[k - 1] * delta[k]);
  }
  const std::size_t m = n - 1;
  const double sum = h[m - 2] + h[m - 1];
  lower[m] = sum;
  diagonal[m] = h[m - 2];
  rhs[m] = (h[m - 1] * h[m - 1] * delta[m - 2] + (2.0 * sum + h[m - 1]) * h[m - 2] * delta[m - 1]) / sum;
  solveTridiagonal(lower, diagonal, upper, rhs);
  slopes_ = rhs;
}

int CubicSpline::interval(double t) const
{
  const int n = numSamples();
  if (n < 2) {
    return 0;
  }
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  const int k = static_cast<int>(it - times_.begin()) - 1;
  return std::clamp(k, 0, n - 2);
}

double CubicSpline::value(double t) const
{
  if (numSamples() == 1) {
    return values_[0];
  }
  const int k = interval(t);
  const double h = times_[k + 1] - times_[k];
  const double s = (t - times_[k]) / h;
  // Cubic Hermite basis on [t_k, t_k+1].
  const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s);
  const double h10 = s * (1.0 - s) * (1.0 - s);
  const double h01 = s * s * (3.0 - 2.0 * s);
  const double h11 = s * s * (s - 1.0);
  return h00 * values_[k] + h10 * h * slopes_[k] + h01 * values_[k + 1] + h11 * h * slopes_[k + 1];
}

double CubicSpline::derivative(double t) const
{
  if (numSamples() == 1) {
    return 0.0;
  }
  const int k = interval(t);
  const double h = times_[k + 1] - times_[k];
  const double s = (t - times_[k]) / h;
  const double d00 = 6.0 * s * (s - 1.0) / h;
  const double d10 = (1.0 - s) * (1.0 - 3.0 * s);
  const double d01 = -d00;
  const double d11 = s * (3.0 * s - 2.0);
  return d00 * values_[k] + d10 * slopes_[k] + d01 * values_[k + 1] + d11 * slopes_[k + 1];
}

} // namespace capsula::scene
