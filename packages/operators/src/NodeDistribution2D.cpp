#include "capsula/operators/NodeDistribution2D.hpp"

#include <capsula/core/Error.hpp>

#include <Tpetra_Vector.hpp>

#include <algorithm>

namespace capsula::operators {

NodeDistribution2D::NodeDistribution2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes)
  : comm_(comm), numNodes_(numNodes)
{
  core::require<core::InputError>(numNodes > 0, "a 2D node distribution needs nodes, got ", numNodes);
  const Map nodes(static_cast<Tpetra::global_size_t>(numNodes), 0, comm_);
  numOwned_ = static_cast<int>(nodes.getNodeNumElements());
  firstNode_ = numOwned_ > 0 ? static_cast<int>(nodes.getMinGlobalIndex()) : 0;
  map_ = Teuchos::rcp(new Map(2 * static_cast<Tpetra::global_size_t>(numNodes),
                              2 * static_cast<std::size_t>(numOwned_), 0, comm_));
  replicatedMap_ = Teuchos::rcp(new Map(2 * static_cast<Tpetra::global_size_t>(numNodes), 0, comm_,
                                        Tpetra::LocallyReplicated));
  gather_ = Teuchos::rcp(new Tpetra::Import<>(map_, replicatedMap_));
}

std::vector<double> NodeDistribution2D::gather(const std::vector<double>& ownedRows) const
{
  core::require(ownedRows.size() == 2 * static_cast<std::size_t>(numOwned_),
                "NodeDistribution2D::gather: 2 values per owned node expected, got ", ownedRows.size());
  Tpetra::Vector<double> owned(map_);
  {
    auto data = owned.getDataNonConst();
    std::copy(ownedRows.begin(), ownedRows.end(), data.begin());
  }
  Tpetra::Vector<double> all(replicatedMap_);
  all.doImport(owned, *gather_, Tpetra::INSERT);
  const auto data = all.getData();
  return std::vector<double>(data.begin(), data.end());
}

} // namespace capsula::operators
