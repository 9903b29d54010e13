#include "capsula/operators/SecondKindOperator2D.hpp"

#include <capsula/core/Error.hpp>

#include <stdexcept>

namespace capsula::operators {

SecondKindOperator2D::SecondKindOperator2D(Teuchos::RCP<const Map> map, DoubleLayerRows doubleLayer,
                                           double coefficient, std::vector<char> fixedRow)
  : map_(std::move(map)),
    replicatedMap_(Teuchos::rcp(new Map(map_->getGlobalNumElements(), 0, map_->getComm(),
                                        Tpetra::LocallyReplicated))),
    gather_(Teuchos::rcp(new Tpetra::Import<>(map_, replicatedMap_))),
    doubleLayer_(std::move(doubleLayer)),
    coefficient_(coefficient),
    fixedRow_(std::move(fixedRow))
{
  core::require(2 * fixedRow_.size() == map_->getNodeNumElements(),
                "SecondKindOperator2D: one fixed-row flag per owned node expected.");
}

void SecondKindOperator2D::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
                                 double beta) const
{
  if (mode != Teuchos::NO_TRANS) {
    throw std::invalid_argument("SecondKindOperator2D has no transpose apply (hasTransposeApply() is false).");
  }
  MultiVector all(replicatedMap_, X.getNumVectors());
  all.doImport(X, *gather_, Tpetra::INSERT);
  const std::size_t numOwned = map_->getNodeNumElements();
  density_.resize(all.getLocalLength());
  rows_.resize(numOwned);
  for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
    const auto u = all.getData(v);
    std::copy(u.begin(), u.end(), density_.begin());
    doubleLayer_(density_.data(), rows_.data());
    ++applications_;
    const auto x = X.getData(v);
    auto y = Y.getDataNonConst(v);
    for (std::size_t k = 0; k < numOwned; ++k) {
      const double Au = fixedRow_[k / 2] ? x[k] : x[k] - coefficient_ * rows_[k];
      y[k] = (beta == 0.0 ? 0.0 : beta * y[k]) + alpha * Au;
    }
  }
}

} // namespace capsula::operators
