#pragma once
// Helpers shared by the Green's function tests: fixed-size tensors filled through the
// kernel policies, and fourth-order central differences.
#include <array>
#include <cmath>

namespace capsula::greens::testing {

template <int D>
using Vec = std::array<double, D>;

template <class Kernel>
struct Tensors {
  static constexpr int D = Kernel::dimension;
  double G[D][D];
  double T[D][D][D];
  double P[D];

  Tensors(const Vec<D>& x, const Vec<D>& x0)
  {
    Kernel::stokeslet(x.data(), x0.data(), G);
    Kernel::stresslet(x.data(), x0.data(), T);
    Kernel::pressure(x.data(), x0.data(), P);
  }
};

/// d f(x)/dx_axis by the 5-point stencil: error step^4 f^(5) / 30 plus ~eps |f| / step.
template <int D, class Function>
double centralDifference(const Function& f, Vec<D> x, int axis, double step)
{
  const double x0 = x[axis];
  auto at = [&](double offset) {
    x[axis] = x0 + offset;
    return f(x);
  };
  return (-at(2 * step) + 8 * at(step) - 8 * at(-step) + at(-2 * step)) / (12 * step);
}

template <int D>
Vec<D> minus(const Vec<D>& a, const Vec<D>& b)
{
  Vec<D> c{};
  for (int i = 0; i < D; ++i) {
    c[i] = a[i] - b[i];
  }
  return c;
}

template <int D>
double norm(const Vec<D>& a)
{
  double s = 0.0;
  for (int i = 0; i < D; ++i) {
    s += a[i] * a[i];
  }
  return std::sqrt(s);
}

} // namespace capsula::greens::testing
