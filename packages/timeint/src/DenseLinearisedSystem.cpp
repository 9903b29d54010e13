#include "capsula/timeint/DenseLinearisedSystem.hpp"

#include "capsula/core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace capsula::timeint {

DenseLinearisedSystem::DenseLinearisedSystem(JacobianFunction jacobian) : jacobianFunction_(std::move(jacobian))
{
  core::require(static_cast<bool>(jacobianFunction_), "internal: DenseLinearisedSystem needs a Jacobian");
}

DenseLinearisedSystem DenseLinearisedSystem::finiteDifferences(RightHandSide rhs, StageConstraint constraint)
{
  return DenseLinearisedSystem([rhs = std::move(rhs), constraint = std::move(constraint)](
                                   double t, const std::vector<double>& y, std::vector<double>& J) {
    const std::size_t n = y.size();
    std::vector<double> f0(n), f1(n), probe(y);
    rhs(t, y, f0);
    if (constraint) {
      constraint(t, y, f0);
    }
    for (std::size_t k = 0; k < n; ++k) {
      // Forward differences: a step of 1e-7 relative balances truncation (O(step)) and
      // round-off (1e-16 / step) near their common minimum.
      const double step = 1e-7 * std::max(1.0, std::abs(y[k]));
      probe[k] = y[k] + step;
      rhs(t, probe, f1);
      if (constraint) {
        constraint(t, probe, f1);
      }
      probe[k] = y[k];
      for (std::size_t i = 0; i < n; ++i) {
        J[i * n + k] = (f1[i] - f0[i]) / step;
      }
    }
  });
}

void DenseLinearisedSystem::linearise(double t, const std::vector<double>& y)
{
  const std::size_t n = y.size();
  jacobian_.assign(n * n, 0.0);
  jacobianFunction_(t, y, jacobian_);
  factorised_ = false;
  ++linearisations_;
}

void DenseLinearisedSystem::factorise(double shift)
{
  const std::size_t n = static_cast<std::size_t>(std::lround(std::sqrt(static_cast<double>(jacobian_.size()))));
  lu_.resize(n * n);
  for (std::size_t i = 0; i < n * n; ++i) {
    lu_[i] = -shift * jacobian_[i];
  }
  for (std::size_t i = 0; i < n; ++i) {
    lu_[i * n + i] += 1.0;
  }
  pivot_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t best = k;
    for (std::size_t i = k + 1; i < n; ++i) {
      if (std::abs(lu_[i * n + k]) > std::abs(lu_[best * n + k])) {
        best = i;
      }
    }
    pivot_[k] = static_cast<int>(best);
    if (best != k) {
      for (std::size_t j = 0; j < n; ++j) {
        std::swap(lu_[k * n + j], lu_[best * n + j]);
      }
    }
    const double diagonal = lu_[k * n + k];
    core::require<core::NumericalError>(diagonal != 0.0, "The matrix I - ", shift,
                                        " J of the linearly implicit step is singular.");
    for (std::size_t i = k + 1; i < n; ++i) {
      const double factor = lu_[i * n + k] / diagonal;
      lu_[i * n + k] = factor;
      for (std::size_t j = k + 1; j < n; ++j) {
        lu_[i * n + j] -= factor * lu_[k * n + j];
      }
    }
  }
  factorisedShift_ = shift;
  factorised_ = true;
  ++factorisations_;
}

LinearSolveReport DenseLinearisedSystem::solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                                               double /*residualRms*/)
{
  const std::size_t n = r.size();
  core::require(jacobian_.size() == n * n, "internal: DenseLinearisedSystem::solve before linearise");
  if (!factorised_ || factorisedShift_ != shift) {
    factorise(shift);
  }
  x = r;
  for (std::size_t k = 0; k < n; ++k) {
    std::swap(x[k], x[static_cast<std::size_t>(pivot_[k])]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      x[i] -= lu_[i * n + j] * x[j];
    }
  }
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t j = i + 1; j < n; ++j) {
      x[i] -= lu_[i * n + j] * x[j];
    }
    x[i] /= lu_[i * n + i];
  }
  LinearSolveReport report;
  report.converged = true;
  return report;
}

} // namespace capsula::timeint
