#include "capsula/operators/SecondKindOperator.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>

#include <algorithm>
#include <stdexcept>

namespace capsula::operators {

SecondKindOperator::SecondKindOperator(Teuchos::RCP<const Map> map, DoubleLayerRows doubleLayer,
                                       std::vector<double> densityScale, std::vector<double> rowScale,
                                       int unknownsPerNode)
    : map_(std::move(map)),
      replicatedMap_(
          Teuchos::rcp(new Map(map_->getGlobalNumElements(), 0, map_->getComm(), Tpetra::LocallyReplicated))),
      gather_(Teuchos::rcp(new Tpetra::Import<>(map_, replicatedMap_))),
      doubleLayer_(std::move(doubleLayer)),
      densityScale_(std::move(densityScale)),
      rowScale_(std::move(rowScale)),
      unknownsPerNode_(static_cast<std::size_t>(unknownsPerNode)),
      timer_(core::timer("Double-layer application"))
{
  core::require(unknownsPerNode == 2 || unknownsPerNode == 3, "SecondKindOperator: 2 or 3 unknowns per node, not ",
                unknownsPerNode, ".");
  core::require(densityScale_.empty() || unknownsPerNode_ * densityScale_.size() == map_->getGlobalNumElements(),
                "SecondKindOperator: one density factor per node expected.");
  core::require(unknownsPerNode_ * rowScale_.size() == map_->getNodeNumElements(),
                "SecondKindOperator: one row factor per owned node expected.");
}

void SecondKindOperator::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
                               double beta) const
{
  if (mode != Teuchos::NO_TRANS) {
    throw std::invalid_argument("SecondKindOperator has no transpose apply (hasTransposeApply() is false).");
  }
  MultiVector all(replicatedMap_, X.getNumVectors());
  all.doImport(X, *gather_, Tpetra::INSERT);
  const std::size_t numOwned = map_->getNodeNumElements();
  density_.resize(all.getLocalLength());
  rows_.resize(numOwned);
  for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
    const auto u = all.getData(v);
    if (densityScale_.empty()) {
      std::copy(u.begin(), u.end(), density_.begin());
    } else {
      for (std::size_t k = 0; k < density_.size(); ++k) {
        density_[k] = densityScale_[k / unknownsPerNode_] * u[k];
      }
    }
    {
      Teuchos::TimeMonitor guard(*timer_);
      doubleLayer_(density_.data(), rows_.data());
    }
    ++applications_;
    const auto x = X.getData(v);
    auto y = Y.getDataNonConst(v);
    for (std::size_t k = 0; k < numOwned; ++k) {
      const double scale = rowScale_[k / unknownsPerNode_];
      const double Au = scale == 0.0 ? x[k] : x[k] - scale * rows_[k];
      y[k] = (beta == 0.0 ? 0.0 : beta * y[k]) + alpha * Au;
    }
  }
}

} // namespace capsula::operators
