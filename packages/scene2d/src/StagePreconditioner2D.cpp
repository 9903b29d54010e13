#include "capsula/scene2d/StagePreconditioner2D.hpp"

#include <capsula/core/Error.hpp>

#include <stdexcept>
#include <utility>

namespace capsula::scene2d {

StagePreconditioner2D::StagePreconditioner2D(Teuchos::RCP<const Map> map) : map_(std::move(map))
{
  core::require(!map_->isDistributed(), "StagePreconditioner2D: the map must be locally replicated");
}

void StagePreconditioner2D::setJacobian(Eigen::MatrixXf approximateJacobian)
{
  const auto n = static_cast<Eigen::Index>(map_->getNodeNumElements());
  core::require(approximateJacobian.rows() == n && approximateJacobian.cols() == n, "StagePreconditioner2D: a ",
                approximateJacobian.rows(), " x ", approximateJacobian.cols(), " Jacobian for ", n, " unknowns");
  jacobian_ = std::move(approximateJacobian);
  factorised_ = false;
}

void StagePreconditioner2D::setShift(double shift)
{
  core::require(jacobian_.size() > 0, "StagePreconditioner2D: setJacobian before setShift");
  if (factorised_ && shift == shift_) {
    return;
  }
  Eigen::MatrixXf P = -static_cast<float>(shift) * jacobian_;
  P.diagonal().array() += 1.0f;
  lu_.compute(P);
  // PartialPivLU does not report singularity; a zero or non-finite pivot shows in the
  // determinant's factors, the diagonal of U.
  const Eigen::VectorXf pivots = lu_.matrixLU().diagonal();
  core::require<core::NumericalError>(pivots.allFinite() && (pivots.array() != 0.0f).all(),
                                      "The preconditioner of the stiff stage solve is singular (shift ", shift,
                                      "): set 'Solver/Stiff/Preconditioner' to None.");
  shift_ = shift;
  factorised_ = true;
}

void StagePreconditioner2D::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
                                  double beta) const
{
  if (mode != Teuchos::NO_TRANS) {
    throw std::invalid_argument("StagePreconditioner2D has no transpose apply.");
  }
  core::require(factorised_, "StagePreconditioner2D: setShift before apply");
  const auto n = static_cast<Eigen::Index>(map_->getNodeNumElements());
  for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
    const auto x = X.getData(v);
    auto y = Y.getDataNonConst(v);
    local_.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      local_[k] = static_cast<float>(x[static_cast<std::size_t>(k)]);
    }
    solved_ = lu_.solve(local_);
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      y[i] = (beta == 0.0 ? 0.0 : beta * y[i]) + alpha * static_cast<double>(solved_[k]);
    }
  }
}

} // namespace capsula::scene2d
