#pragma once
// How the rows of the boundary-integral equation are spread over the ranks, in 2D and 3D:
// whole nodes, contiguous in the global numbering (Tpetra's uniform map over the nodes),
// `unknownsPerNode` (2 or 3) unknowns per node with GID d g + i. Gathers owned rows back
// to every rank with a Tpetra::Import built once, and splits lists of flow points the
// same way.
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>

#include <utility>
#include <vector>

namespace capsula::operators {

class NodeDistribution {
public:
  using Map = Tpetra::Map<>;

  /// Throws core::InputError for no nodes or another number of unknowns per node than 2 or 3.
  NodeDistribution(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes, int unknownsPerNode = 3);

  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }
  int numNodes() const { return numNodes_; }
  int unknownsPerNode() const { return unknownsPerNode_; }
  /// unknownsPerNode() unknowns per node, distributed.
  const Teuchos::RCP<const Map>& map() const { return map_; }
  int firstOwnedNode() const { return firstNode_; }
  int numOwnedNodes() const { return numOwned_; }

  /// The rows of every node on every rank, from the owned rows (unknownsPerNode() per
  /// owned node). Collective.
  std::vector<double> gather(const std::vector<double>& ownedRows) const;

  /// This rank's share [first, end) of n items (contiguous, balanced).
  std::pair<int, int> share(int n) const;
  /// All n items of `width` values on every rank, from this rank's share (values for
  /// share(n) only). Collective.
  std::vector<double> gatherShares(const std::vector<double>& shareValues, int n, int width) const;

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  int numNodes_ = 0;
  int unknownsPerNode_ = 3;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<const Tpetra::Import<>> gather_;
  int firstNode_ = 0;
  int numOwned_ = 0;
};

} // namespace capsula::operators
