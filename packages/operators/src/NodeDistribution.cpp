#include "capsula/operators/NodeDistribution.hpp"

#include <capsula/core/Error.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>

namespace capsula::operators {

NodeDistribution::NodeDistribution(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                                   int unknownsPerNode)
    : comm_(comm), numNodes_(numNodes), unknownsPerNode_(unknownsPerNode)
{
  core::require<core::InputError>(numNodes > 0, "a node distribution needs nodes, got ", numNodes);
  core::require<core::InputError>(unknownsPerNode == 2 || unknownsPerNode == 3,
                                  "a node distribution has 2 or 3 unknowns per node, not ", unknownsPerNode);
  const Map nodes(static_cast<Tpetra::global_size_t>(numNodes), 0, comm_);
  numOwned_ = static_cast<int>(nodes.getNodeNumElements());
  firstNode_ = numOwned_ > 0 ? static_cast<int>(nodes.getMinGlobalIndex()) : 0;
  const auto stride = static_cast<std::size_t>(unknownsPerNode);
  map_ = Teuchos::rcp(new Map(stride * static_cast<Tpetra::global_size_t>(numNodes),
                              stride * static_cast<std::size_t>(numOwned_), 0, comm_));
  replicatedMap_ =
      Teuchos::rcp(new Map(stride * static_cast<Tpetra::global_size_t>(numNodes), 0, comm_, Tpetra::LocallyReplicated));
  gather_ = Teuchos::rcp(new Tpetra::Import<>(map_, replicatedMap_));
}

std::vector<double> NodeDistribution::gather(const std::vector<double>& ownedRows) const
{
  core::require(ownedRows.size() == static_cast<std::size_t>(unknownsPerNode_) * static_cast<std::size_t>(numOwned_),
                "NodeDistribution::gather: ", unknownsPerNode_, " values per owned node expected, got ",
                ownedRows.size());
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

std::pair<int, int> NodeDistribution::share(int n) const
{
  const int size = comm_->getSize();
  const int rank = comm_->getRank();
  const int base = n / size;
  const int extra = n % size;
  const int first = rank * base + std::min(rank, extra);
  return {first, first + base + (rank < extra ? 1 : 0)};
}

std::vector<double> NodeDistribution::gatherShares(const std::vector<double>& shareValues, int n, int width) const
{
  // Each entry is written by one rank and zero on the others: the sum is exact.
  std::vector<double> mine(static_cast<std::size_t>(n) * width, 0.0);
  const auto [first, end] = share(n);
  std::copy(shareValues.begin(), shareValues.begin() + static_cast<std::ptrdiff_t>(end - first) * width,
            mine.begin() + static_cast<std::ptrdiff_t>(first) * width);
  std::vector<double> all(mine.size(), 0.0);
  if (!mine.empty()) {
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(), all.data());
  }
  return all;
}

} // namespace capsula::operators
