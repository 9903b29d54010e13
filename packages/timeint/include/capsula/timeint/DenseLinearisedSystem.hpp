#pragma once
// A LinearisedSystem with a dense J~ (n x n) and LU solves: for small systems (tests,
// model problems), never for a capsule. J~ comes from a function (exact, or a deliberate
// approximation to exercise the W-method property) or from forward differences of the
// right-hand side, n extra evaluations per linearisation.
#include "capsula/timeint/LinearisedSystem.hpp"
#include "capsula/timeint/TimeIntegrator.hpp"

#include <functional>
#include <vector>

namespace capsula::timeint {

class DenseLinearisedSystem final : public LinearisedSystem {
public:
  /// Writes J~(t, y) row-major into J (n * n entries, sized by the caller).
  using JacobianFunction = std::function<void(double t, const std::vector<double>& y, std::vector<double>& J)>;

  explicit DenseLinearisedSystem(JacobianFunction jacobian);

  /// J~ by forward differences of `rhs` followed by `constraint` (if any), the step in
  /// coordinate k being 1e-7 max(1, |y_k|).
  static DenseLinearisedSystem finiteDifferences(RightHandSide rhs, StageConstraint constraint = {});

  void linearise(double t, const std::vector<double>& y) override;
  LinearSolveReport solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                          double residualRms) override;
  std::string settingsHint() const override { return "(a dense direct solve has no settings)"; }

  int linearisations() const { return linearisations_; }
  int factorisations() const { return factorisations_; }
  const std::vector<double>& jacobian() const { return jacobian_; }

private:
  void factorise(double shift);

  JacobianFunction jacobianFunction_;
  std::vector<double> jacobian_; // J~, row-major
  std::vector<double> lu_;       // LU of I - shift J~ with partial pivoting
  std::vector<int> pivot_;
  double factorisedShift_ = 0.0;
  bool factorised_ = false;
  int linearisations_ = 0;
  int factorisations_ = 0;
};

} // namespace capsula::timeint
