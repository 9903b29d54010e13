#pragma once
// The preconditioner of the 2D stiff stage solves (VelocityJacobian2D.hpp): the stage
// matrix W = I - shift J~ with J~ replaced by a dense approximation A that is cheap to
// form, P = I - shift A, LU-factorised (partial pivoting) once per shift and applied as
// P^-1 on the right of flexible GMRES. In 2D the system has 2N <= 2048 unknowns, so the
// O((2N)^3) factorisation costs a few right-hand sides at the thesis's N = 256 (the
// measured split is in docs/stiff-integration.md). A is held and factorised in single
// precision, twice as fast as in double: A itself is only a percent-level approximation of
// J~, and flexible GMRES takes whatever P^-1 gives it. Every rank factorises and applies P to the whole
// (replicated) vector, with the same bits.
#include <Eigen/Core>
#include <Eigen/LU>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

namespace capsula::scene2d {

class StagePreconditioner2D final : public Tpetra::Operator<double> {
public:
  using Map = Tpetra::Map<>;
  using MultiVector = Tpetra::MultiVector<double>;

  /// `map`: locally replicated, 2 unknowns per node.
  explicit StagePreconditioner2D(Teuchos::RCP<const Map> map);

  /// A, the approximate Jacobian (square, the map's size). Refactorises at the next setShift.
  void setJacobian(Eigen::MatrixXf approximateJacobian);
  const Eigen::MatrixXf& jacobian() const { return jacobian_; }
  /// Factorises I - shift A (nothing if neither the shift nor A has changed).
  void setShift(double shift);

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }
  /// Y = alpha P^-1 X + beta Y. Throws std::invalid_argument for a transpose.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override;

private:
  Teuchos::RCP<const Map> map_;
  Eigen::MatrixXf jacobian_;
  Eigen::PartialPivLU<Eigen::MatrixXf> lu_;
  double shift_ = 0.0;
  bool factorised_ = false;
  mutable Eigen::VectorXf local_, solved_;
};

} // namespace capsula::scene2d
