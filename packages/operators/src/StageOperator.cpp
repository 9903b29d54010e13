#include "capsula/operators/StageOperator.hpp"

#include <capsula/core/Error.hpp>

#include <stdexcept>

namespace capsula::operators {

StageOperator::StageOperator(Teuchos::RCP<const Map> map, Action jacobian)
    : map_(std::move(map)), jacobian_(std::move(jacobian))
{
  core::require(!map_->isDistributed(), "StageOperator: the map must be locally replicated");
  core::require(static_cast<bool>(jacobian_), "StageOperator: no Jacobian action");
}

void StageOperator::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha, double beta) const
{
  if (mode != Teuchos::NO_TRANS) {
    throw std::invalid_argument("StageOperator has no transpose apply (hasTransposeApply() is false).");
  }
  const std::size_t n = map_->getNodeNumElements();
  product_.resize(n);
  for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
    const auto x = X.getData(v);
    jacobian_(x.getRawPtr(), product_.data());
    ++applications_;
    if (products_ != nullptr) {
      products_->add(x.getRawPtr(), product_.data(), n);
    }
    auto y = Y.getDataNonConst(v);
    for (std::size_t k = 0; k < n; ++k) {
      const double Wx = x[k] - shift_ * product_[k];
      y[k] = (beta == 0.0 ? 0.0 : beta * y[k]) + alpha * Wx;
    }
  }
}

} // namespace capsula::operators
