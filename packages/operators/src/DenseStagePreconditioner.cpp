#include "capsula/operators/DenseStagePreconditioner.hpp"

#include <capsula/core/Error.hpp>

#include <utility>

namespace capsula::operators {

DenseStagePreconditioner::DenseStagePreconditioner(Teuchos::RCP<const Map> map)
    : StagePreconditioner(std::move(map), "DenseStagePreconditioner")
{}

void DenseStagePreconditioner::setJacobian(Eigen::MatrixXf approximateJacobian)
{
  const auto n = static_cast<Eigen::Index>(map().getNodeNumElements());
  core::require(approximateJacobian.rows() == n && approximateJacobian.cols() == n, name(), ": a ",
                approximateJacobian.rows(), " x ", approximateJacobian.cols(), " Jacobian for ", n, " unknowns");
  jacobian_ = std::move(approximateJacobian);
  approximationChanged();
}

void DenseStagePreconditioner::factorise(double shift)
{
  core::require(jacobian_.size() > 0, name(), ": setJacobian before setShift");
  Eigen::MatrixXf P = -static_cast<float>(shift) * jacobian_;
  P.diagonal().array() += 1.0f;
  lu_.compute(P);
  // PartialPivLU does not report singularity; a zero or non-finite pivot shows in the
  // determinant's factors, the diagonal of U.
  const Eigen::VectorXf pivots = lu_.matrixLU().diagonal();
  core::require<core::NumericalError>(pivots.allFinite() && (pivots.array() != 0.0f).all(),
                                      "The preconditioner of the stiff stage solve is singular (shift ", shift,
                                      "): set 'Solver/Stiff/Preconditioner' to None.");
}

void DenseStagePreconditioner::solve(const double* x, double* z) const
{
  const auto n = static_cast<Eigen::Index>(map().getNodeNumElements());
  local_.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    local_[k] = static_cast<float>(x[k]);
  }
  solved_ = lu_.solve(local_);
  for (Eigen::Index k = 0; k < n; ++k) {
    z[k] = static_cast<double>(solved_[k]);
  }
}

} // namespace capsula::operators
