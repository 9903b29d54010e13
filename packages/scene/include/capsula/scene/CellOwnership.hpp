#pragma once
// Which rank holds a cell's membrane mechanics. The state (every node's position) and the
// boundary-integral geometry are on every rank, but a membrane's precomputed reference
// geometry, bending operator, mass matrix and, with a stiff method, its tangent stiffness
// and preconditioner block are held only by the cell's owner: they are most of a rank's
// heap in a suspension (docs/suspension3d.md, "Memory per rank"), and replicating them
// would keep memory per rank flat as ranks are added.
//
// Cells go to ranks in contiguous runs balanced by their nodes: cell c belongs to rank
// floor(P m_c / N), m_c the number of the cell's middle node, N the nodes of the scene, P
// the ranks. A rank computes what belongs to its cells (loads, tensions, stiffness
// products) and share() completes the arrays on every rank. A value computed by one rank
// is the same whatever the number of ranks, so results do not depend on it.
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

namespace capsula::scene {

class CellOwnership {
public:
  /// For cells of `nodesPerCell` nodes over the ranks of `comm`. Throws core::InputError
  /// for a cell without nodes.
  CellOwnership(Teuchos::RCP<const Teuchos::Comm<int>> comm, const std::vector<int>& nodesPerCell);

  int numCells() const { return static_cast<int>(owners_.size()); }
  int owner(int cell) const { return owners_[static_cast<std::size_t>(cell)]; }
  bool owns(int cell) const { return owner(cell) == rank_; }
  /// The cells of this rank.
  int numOwned() const;
  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }

  /// Completes `values` on every rank: cell c's entries [offsets[c], offsets[c + 1]) are
  /// taken from its owner, whatever other ranks held there. `offsets` has numCells() + 1
  /// entries. Collective.
  void share(std::vector<double>& values, const std::vector<std::size_t>& offsets) const;

  /// Runs work(c) for every cell this rank owns, in order, and makes its errors collective:
  /// if it throws for some cell on some rank, every rank throws the error of the lowest such
  /// cell with the same message, as one rank running every cell would: the owner rethrows
  /// it, the other ranks throw the same type (core::InputError, core::NumericalError,
  /// core::IoError, timeint::StateOutsideDomain; else core::Error). Collective.
  template <typename Work>
  void forEachOwnedCell(Work&& work) const
  {
    Failure failure;
    for (int c = 0; c < numCells() && failure.cell < 0; ++c) {
      if (owns(c)) {
        try {
          work(c);
        } catch (...) {
          failure = describeCurrentException(c);
        }
      }
    }
    raiseLowestFailure(failure);
  }

  /// Runs work() on the owner of `cell` only, with its errors made collective as above.
  template <typename Work>
  void onOwner(int cell, Work&& work) const
  {
    Failure failure;
    if (owns(cell)) {
      try {
        work();
      } catch (...) {
        failure = describeCurrentException(cell);
      }
    }
    raiseLowestFailure(failure);
  }

private:
  struct Failure {
    int cell = -1;
    int kind = 0;
    std::string message;
    std::exception_ptr error; // rethrown as it is on the rank that caught it
  };
  static Failure describeCurrentException(int cell);
  void raiseLowestFailure(const Failure& failure) const;

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  int rank_ = 0;
  std::vector<int> owners_;
};

} // namespace capsula::scene
