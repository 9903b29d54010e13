#include "capsula/operators/StagePreconditioner.hpp"

#include <capsula/core/Error.hpp>

#include <stdexcept>
#include <utility>

namespace capsula::operators {

StagePreconditioner::StagePreconditioner(Teuchos::RCP<const Map> map, std::string name)
    : map_(std::move(map)), name_(std::move(name))
{
  core::require(!map_->isDistributed(), name_, ": the map must be locally replicated");
}

void StagePreconditioner::setShift(double shift)
{
  if (factorisedShift_ && *factorisedShift_ == shift) {
    return;
  }
  factorisedShift_.reset(); // a failed factorisation leaves none
  factorise(shift);
  factorisedShift_ = shift;
}

void StagePreconditioner::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
                                double beta) const
{
  if (mode != Teuchos::NO_TRANS) {
    throw std::invalid_argument(name_ + " has no transpose apply.");
  }
  core::require(factorisedShift_.has_value(), name_, ": setShift before apply");
  const std::size_t n = map_->getNodeNumElements();
  solved_.resize(n);
  for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
    const auto x = X.getData(v);
    auto y = Y.getDataNonConst(v);
    solve(x.getRawPtr(), solved_.data());
    for (std::size_t k = 0; k < n; ++k) {
      y[k] = (beta == 0.0 ? 0.0 : beta * y[k]) + alpha * solved_[k];
    }
  }
}

} // namespace capsula::operators
