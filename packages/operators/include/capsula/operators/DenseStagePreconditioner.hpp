#pragma once
// A stage preconditioner (StagePreconditioner.hpp) from a dense approximation A of J~ that
// is cheap to form: P = I - shift A, LU-factorised (partial pivoting) once per shift and
// applied as P^-1 on the right of flexible GMRES. The 2D cell's stiff solves use it
// (scene2d/VelocityJacobian2D.hpp): there the system has 2N <= 2048 unknowns, so the
// O((2N)^3) factorisation costs a few right-hand sides at the thesis's N = 256 (the measured
// split is in docs/stiff-integration.md). A is held and factorised in single precision,
// twice as fast as in double: A itself is only a percent-level approximation of J~, and
// flexible GMRES takes whatever P^-1 gives it.
#include <capsula/operators/StagePreconditioner.hpp>

#include <Eigen/Core>
#include <Eigen/LU>

namespace capsula::operators {

class DenseStagePreconditioner final : public StagePreconditioner {
public:
  /// `map`: locally replicated.
  explicit DenseStagePreconditioner(Teuchos::RCP<const Map> map);

  /// A, the approximate Jacobian (square, the map's size). Refactorises at the next setShift.
  void setJacobian(Eigen::MatrixXf approximateJacobian);
  const Eigen::MatrixXf& jacobian() const { return jacobian_; }

private:
  void factorise(double shift) override;
  void solve(const double* x, double* z) const override;

  Eigen::MatrixXf jacobian_;
  Eigen::PartialPivLU<Eigen::MatrixXf> lu_;
  mutable Eigen::VectorXf local_, solved_;
};

} // namespace capsula::operators
