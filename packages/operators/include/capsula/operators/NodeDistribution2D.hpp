#pragma once
// The rows of the 2D boundary-integral equation spread over the ranks: whole nodes,
// contiguous (Tpetra's uniform map over the nodes), 2 unknowns per node with GID 2 g + i.
// The 2D twin of NodeDistribution (3 unknowns per node): the same pattern with another
// stride. Gathers the owned rows back to every rank with a Tpetra::Import built once.
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>

#include <vector>

namespace capsula::operators {

class NodeDistribution2D {
public:
  using Map = Tpetra::Map<>;

  NodeDistribution2D(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes);

  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }
  int numNodes() const { return numNodes_; }
  /// 2 unknowns per node, distributed.
  const Teuchos::RCP<const Map>& map() const { return map_; }
  int firstOwnedNode() const { return firstNode_; }
  int numOwnedNodes() const { return numOwned_; }

  /// The rows of every node on every rank (2 per node), from the owned rows (2 per owned
  /// node). Collective.
  std::vector<double> gather(const std::vector<double>& ownedRows) const;

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  int numNodes_ = 0;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<const Tpetra::Import<>> gather_;
  int firstNode_ = 0;
  int numOwned_ = 0;
};

} // namespace capsula::operators
