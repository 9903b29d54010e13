#pragma once
// Small ODEs with exact solutions and the error between two states.
#include "capsula/timeint/TimeIntegrator.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace capsula::timeint::testing {

struct TestProblem {
  std::string name;
  RightHandSide rhs;
  std::vector<double> y0;
  std::vector<double> (*exact)(double t);
};

/// y' = -y, y(0) = 1.
inline TestProblem exponentialDecay()
{
  return {"y' = -y",
          [](double, const std::vector<double>& y, std::vector<double>& f) { f[0] = -y[0]; },
          {1.0},
          [](double t) { return std::vector<double>{std::exp(-t)}; }};
}

/// y' = cos t, y(0) = 0: pure quadrature, tests the stage times c_i.
inline TestProblem cosine()
{
  return {"y' = cos t",
          [](double t, const std::vector<double>&, std::vector<double>& f) { f[0] = std::cos(t); },
          {0.0},
          [](double t) { return std::vector<double>{std::sin(t)}; }};
}

/// (x, y)' = (-y, x), (x, y)(0) = (1, 0): rotation of the unit vector.
inline TestProblem rotation()
{
  return {"2D rotation",
          [](double, const std::vector<double>& y, std::vector<double>& f) {
            f[0] = -y[1];
            f[1] = y[0];
          },
          {1.0, 0.0},
          [](double t) {
            return std::vector<double>{std::cos(t), std::sin(t)};
          }};
}

/// y' = -5 (y - cos t), y(0) = 1: relaxes onto a moving target (time scale 1/5 against
/// period 2 pi), smooth and non-stiff for explicit methods at moderate steps.
inline TestProblem relaxation()
{
  return {"y' = -5 (y - cos t)",
          [](double t, const std::vector<double>& y, std::vector<double>& f) { f[0] = -5.0 * (y[0] - std::cos(t)); },
          {1.0},
          [](double t) {
            return std::vector<double>{(25.0 * std::cos(t) + 5.0 * std::sin(t)) / 26.0 + std::exp(-5.0 * t) / 26.0};
          }};
}

inline double maxError(const std::vector<double>& a, const std::vector<double>& b)
{
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    e = std::max(e, std::abs(a[i] - b[i]));
  }
  return e;
}

} // namespace capsula::timeint::testing
