#include "capsula/operators/CellBlockPreconditioner.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace capsula::operators {

namespace {

// P_c = I - s D_cc from its full rows (3 n x 3 n, row-major, double), in single precision.
Eigen::MatrixXf blockMatrix(const double* rows, int numNodes, double scale)
{
  const int n = 3 * numNodes;
  Eigen::MatrixXf P(n, n);
  for (int r = 0; r < n; ++r) {
    for (int k = 0; k < n; ++k) {
      P(r, k) = static_cast<float>((r == k ? 1.0 : 0.0) - scale * rows[static_cast<std::size_t>(r) * n + k]);
    }
  }
  return P;
}

} // namespace

CellBlockPreconditioner::CellBlockPreconditioner(Teuchos::RCP<const Map> map, std::vector<int> cellNodeOffsets,
                                                 std::vector<double> cellScale, const CellRows& rowsOf)
    : map_(std::move(map)),
      replicatedMap_(
          Teuchos::rcp(new Map(map_->getGlobalNumElements(), 0, map_->getComm(), Tpetra::LocallyReplicated))),
      gather_(Teuchos::rcp(new Tpetra::Import<>(map_, replicatedMap_))),
      timer_(core::timer("Cell-block preconditioner"))
{
  Teuchos::TimeMonitor guard(*core::timer("Cell-block preconditioner: assembly and LU"));
  const int numCells = static_cast<int>(cellScale.size());
  core::require(cellNodeOffsets.size() == cellScale.size() + 1 &&
                    3 * static_cast<std::size_t>(cellNodeOffsets.back()) == map_->getGlobalNumElements(),
                "CellBlockPreconditioner: one scale per cell and the cells' node offsets of the map expected.");
  const auto& comm = *map_->getComm();
  numOwnedNodes_ = static_cast<int>(map_->getNodeNumElements() / 3);
  firstOwnedNode_ = numOwnedNodes_ > 0 ? static_cast<int>(map_->getMinGlobalIndex() / 3) : 0;
  // Every rank's node range, to find the cells whose rows lie on several ranks.
  const int mine[2] = {firstOwnedNode_, firstOwnedNode_ + numOwnedNodes_};
  std::vector<int> ranges(2 * static_cast<std::size_t>(comm.getSize()));
  Teuchos::gatherAll(comm, 2, mine, static_cast<int>(ranges.size()), ranges.data());
  const auto ranksHolding = [&](int c) {
    int count = 0;
    for (int p = 0; p < comm.getSize(); ++p) {
      count += std::max(ranges[2 * p], cellNodeOffsets[c]) < std::min(ranges[2 * p + 1], cellNodeOffsets[c + 1]);
    }
    return count;
  };

  std::vector<int> shared; // cells split over ranks, in the same order on every rank
  std::vector<double> rows;
  for (int c = 0; c < numCells; ++c) {
    const int first = cellNodeOffsets[c], numNodes = cellNodeOffsets[c + 1] - first;
    if (cellScale[c] == 0.0 || numNodes == 0) {
      continue;
    }
    if (ranksHolding(c) > 1) {
      shared.push_back(c);
      continue;
    }
    if (std::max(first, mine[0]) >= std::min(first + numNodes, mine[1])) {
      continue; // another rank's cell
    }
    core::require(rowsOf(c, rows) == numNodes, "CellBlockPreconditioner: cell ", c,
                  " is owned whole but its rows are not.");
    blocks_.push_back({c, first, numNodes, Eigen::PartialPivLU<Eigen::MatrixXf>()});
    blocks_.back().lu.compute(blockMatrix(rows.data(), numNodes, cellScale[c]));
  }
  // The split cells' rows summed over the ranks: each contributes its own rows, zero
  // elsewhere, so the sum holds every row exactly once.
  std::size_t total = 0;
  for (const int c : shared) {
    const std::size_t n = 3 * static_cast<std::size_t>(cellNodeOffsets[c + 1] - cellNodeOffsets[c]);
    total += n * n;
  }
  if (total > 0) {
    std::vector<double> partial(total, 0.0), full(total);
    std::size_t offset = 0;
    for (const int c : shared) {
      const int first = cellNodeOffsets[c], end = cellNodeOffsets[c + 1];
      const std::size_t n = 3 * static_cast<std::size_t>(end - first);
      const int firstRow = std::max(first, mine[0]);
      if (firstRow < std::min(end, mine[1])) {
        core::require(rowsOf(c, rows) == std::min(end, mine[1]) - firstRow, "CellBlockPreconditioner: cell ", c,
                      " got other rows than the rank owns.");
        std::copy(rows.begin(), rows.end(), partial.begin() + offset + 3 * (firstRow - first) * n);
      }
      offset += n * n;
    }
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(total), partial.data(), full.data());
    offset = 0;
    for (const int c : shared) {
      const int first = cellNodeOffsets[c], end = cellNodeOffsets[c + 1];
      const std::size_t n = 3 * static_cast<std::size_t>(end - first);
      if (std::max(first, mine[0]) < std::min(end, mine[1])) {
        blocks_.push_back({c, first, end - first, Eigen::PartialPivLU<Eigen::MatrixXf>()});
        blocks_.back().lu.compute(blockMatrix(full.data() + offset, end - first, cellScale[c]));
      }
      offset += n * n;
    }
  }
  // PartialPivLU does not report a zero pivot (nor NaN in the block): look at U's diagonal.
  // Every rank learns of a bad block, so that all of them throw and none waits in
  // the solve's next collective.
  int singular = -1;
  for (const Block& block : blocks_) {
    const Eigen::VectorXf pivots = block.lu.matrixLU().diagonal().cwiseAbs();
    if (!(pivots.allFinite() && pivots.minCoeff() > 0.0f) && singular < 0) {
      singular = block.cell;
    }
  }
  int first = -1;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, singular, Teuchos::outArg(first));
  core::require<core::NumericalError>(first < 0, "The cell-block preconditioner's block of cell ", first,
                                      " is singular or not finite ('Solver/Preconditioner').");
}

void CellBlockPreconditioner::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
                                    double beta) const
{
  if (mode != Teuchos::NO_TRANS) {
    throw std::invalid_argument("CellBlockPreconditioner has no transpose apply (hasTransposeApply() is false).");
  }
  Teuchos::TimeMonitor guard(*timer_);
  MultiVector all(replicatedMap_, X.getNumVectors());
  all.doImport(X, *gather_, Tpetra::INSERT);
  const std::size_t numOwned = 3 * static_cast<std::size_t>(numOwnedNodes_);
  std::vector<double> z(numOwned);
  for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
    const auto x = all.getData(v);
    for (std::size_t k = 0; k < numOwned; ++k) {
      z[k] = x[3 * static_cast<std::size_t>(firstOwnedNode_) + k];
    }
    for (const Block& block : blocks_) {
      const int n = 3 * block.numNodes;
      Eigen::VectorXf local(n);
      for (int k = 0; k < n; ++k) {
        local[k] = static_cast<float>(x[3 * static_cast<std::size_t>(block.firstNode) + k]);
      }
      const Eigen::VectorXf solved = block.lu.solve(local);
      const int firstRow = std::max(block.firstNode, firstOwnedNode_);
      const int endRow = std::min(block.firstNode + block.numNodes, firstOwnedNode_ + numOwnedNodes_);
      for (int k = 3 * (firstRow - block.firstNode); k < 3 * (endRow - block.firstNode); ++k) {
        z[static_cast<std::size_t>(3 * (block.firstNode - firstOwnedNode_) + k)] = solved[k];
      }
    }
    auto y = Y.getDataNonConst(v);
    for (std::size_t k = 0; k < numOwned; ++k) {
      y[k] = (beta == 0.0 ? 0.0 : beta * y[k]) + alpha * z[k];
    }
  }
}

} // namespace capsula::operators
