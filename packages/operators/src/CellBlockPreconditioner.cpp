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
  // Every rank's node range, to find where a cell's rows lie.
  const int mine[2] = {firstOwnedNode_, firstOwnedNode_ + numOwnedNodes_};
  std::vector<int> ranges(2 * static_cast<std::size_t>(comm.getSize()));
  Teuchos::gatherAll(comm, 2, mine, static_cast<int>(ranges.size()), ranges.data());
  const auto ownsRowsOf = [&](int p, int c) {
    return std::max(ranges[2 * p], cellNodeOffsets[c]) < std::min(ranges[2 * p + 1], cellNodeOffsets[c + 1]);
  };

  // The blocks go to the ranks in contiguous runs balanced by their entries (n_c^2 each):
  // the block whose middle entry is the k-th of W in all goes to rank floor(P k / W).
  std::vector<int> blockCells;
  double entries = 0.0;
  for (int c = 0; c < numCells; ++c) {
    const double n = 3.0 * (cellNodeOffsets[c + 1] - cellNodeOffsets[c]);
    if (cellScale[c] != 0.0 && n > 0.0) {
      blockCells.push_back(c);
      entries += n * n;
    }
  }
  const int ranks = comm.getSize();
  std::vector<int> holders;
  std::vector<int> travelling; // cells with rows on a rank other than their holder, in order
  double before = 0.0;
  for (const int c : blockCells) {
    const double n = 3.0 * (cellNodeOffsets[c + 1] - cellNodeOffsets[c]);
    holders.push_back(std::min(ranks - 1, static_cast<int>(ranks * (before + 0.5 * n * n) / entries)));
    before += n * n;
    bool allRowsOnHolder = true;
    for (int p = 0; p < ranks; ++p) {
      allRowsOnHolder = allRowsOnHolder && (p == holders.back() || !ownsRowsOf(p, c));
    }
    if (!allRowsOnHolder) {
      travelling.push_back(static_cast<int>(holders.size()) - 1);
    }
  }
  // First the blocks a rank computes whole, with no rank waiting on another; then the
  // travelling ones. Room for all of them first: a growing vector would copy the LUs.
  blocks_.reserve(static_cast<std::size_t>(std::count(holders.begin(), holders.end(), comm.getRank())));
  std::vector<double> rows;
  for (std::size_t b = 0; b < blockCells.size(); ++b) {
    const int c = blockCells[b], first = cellNodeOffsets[c], numNodes = cellNodeOffsets[c + 1] - first;
    if (holders[b] == comm.getRank() &&
        std::find(travelling.begin(), travelling.end(), static_cast<int>(b)) == travelling.end()) {
      core::require(rowsOf(c, rows) == numNodes, "CellBlockPreconditioner: cell ", c,
                    " is owned whole but its rows are not.");
      blocks_.push_back({c, first, numNodes, Eigen::PartialPivLU<Eigen::MatrixXf>()});
      blocks_.back().lu.compute(blockMatrix(rows.data(), numNodes, cellScale[c]));
    }
  }
  for (const int b : travelling) {
    const int c = blockCells[static_cast<std::size_t>(b)], holder = holders[static_cast<std::size_t>(b)];
    const int first = cellNodeOffsets[c], end = cellNodeOffsets[c + 1], numNodes = end - first;
    const std::size_t n = 3 * static_cast<std::size_t>(numNodes);
    const bool holding = holder == comm.getRank();
    const int firstRow = std::max(first, mine[0]), endRow = std::min(end, mine[1]);
    // Each rank's own rows of the cell, zero elsewhere, summed on the holder: every row
    // exactly once. One cell at a time, so no rank holds more than one block in transit.
    std::vector<double> partial(n * n, 0.0);
    if (firstRow < endRow) {
      core::require(rowsOf(c, rows) == endRow - firstRow, "CellBlockPreconditioner: cell ", c,
                    " got other rows than the rank owns.");
      std::copy(rows.begin(), rows.end(), partial.begin() + static_cast<std::ptrdiff_t>(3 * (firstRow - first) * n));
    }
    std::vector<double> full(holding ? n * n : 0);
    Teuchos::reduce(partial.data(), full.data(), static_cast<int>(n * n), Teuchos::REDUCE_SUM, holder, comm);
    std::vector<double>().swap(partial); // before the factorisation: one block fewer at the peak
    if (holding) {
      blocks_.push_back({c, first, numNodes, Eigen::PartialPivLU<Eigen::MatrixXf>()});
      blocks_.back().lu.compute(blockMatrix(full.data(), numNodes, cellScale[c]));
    }
  }
  for (const int c : blockCells) {
    blockUnknowns_.push_back(
        {3 * static_cast<std::size_t>(cellNodeOffsets[c]), 3 * static_cast<std::size_t>(cellNodeOffsets[c + 1])});
  }
  // PartialPivLU does not report a zero pivot (nor NaN in the block): look at U's diagonal.
  // Every rank learns of the lowest bad block, so that all of them throw the message one
  // rank would, and none waits in the solve's next collective.
  int singular = numCells;
  for (const Block& block : blocks_) {
    const Eigen::VectorXf pivots = block.lu.matrixLU().diagonal().cwiseAbs();
    if (!(pivots.allFinite() && pivots.minCoeff() > 0.0f)) {
      singular = std::min(singular, block.cell);
    }
  }
  int first = numCells;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, singular, Teuchos::outArg(first));
  core::require<core::NumericalError>(first == numCells, "The cell-block preconditioner's block of cell ", first,
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
  const auto& comm = *map_->getComm();
  const std::size_t numUnknowns = map_->getGlobalNumElements();
  const std::size_t firstOwned = 3 * static_cast<std::size_t>(firstOwnedNode_);
  const std::size_t numOwned = 3 * static_cast<std::size_t>(numOwnedNodes_);
  std::vector<double> solvedHere(numUnknowns), solved(numUnknowns);
  for (std::size_t v = 0; v < X.getNumVectors(); ++v) {
    const auto x = all.getData(v);
    // The blocks this rank holds, zero elsewhere; the sum over the ranks is every block's
    // solution exactly once.
    std::fill(solvedHere.begin(), solvedHere.end(), 0.0);
    for (const Block& block : blocks_) {
      const int n = 3 * block.numNodes;
      const std::size_t first = 3 * static_cast<std::size_t>(block.firstNode);
      Eigen::VectorXf local(n);
      for (int k = 0; k < n; ++k) {
        local[k] = static_cast<float>(x[first + static_cast<std::size_t>(k)]);
      }
      const Eigen::VectorXf z = block.lu.solve(local);
      for (int k = 0; k < n; ++k) {
        solvedHere[first + static_cast<std::size_t>(k)] = z[k];
      }
    }
    if (comm.getSize() > 1) {
      Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(numUnknowns), solvedHere.data(), solved.data());
    } else {
      solved.swap(solvedHere);
    }
    // The rows this rank owns: a block's solution, or x itself in a cell without a block.
    auto y = Y.getDataNonConst(v);
    std::size_t block = 0;
    for (std::size_t k = 0; k < numOwned; ++k) {
      const std::size_t row = firstOwned + k;
      while (block < blockUnknowns_.size() && blockUnknowns_[block].second <= row) {
        ++block;
      }
      const bool inBlock = block < blockUnknowns_.size() && blockUnknowns_[block].first <= row;
      const double z = inBlock ? solved[row] : x[row];
      y[k] = (beta == 0.0 ? 0.0 : beta * y[k]) + alpha * z;
    }
  }
}

} // namespace capsula::operators
