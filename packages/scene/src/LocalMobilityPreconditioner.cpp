#include "capsula/scene/LocalMobilityPreconditioner.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <utility>

namespace capsula::scene {

LocalMobilityPreconditioner::LocalMobilityPreconditioner(Teuchos::RCP<const Map> map, CellOwnership ownership,
                                                         std::vector<int> cellNodeOffsets)
    : StagePreconditioner(std::move(map), "LocalMobilityPreconditioner"), ownership_(std::move(ownership))
{
  core::require(cellNodeOffsets.size() == static_cast<std::size_t>(ownership_.numCells()) + 1,
                "LocalMobilityPreconditioner: ", cellNodeOffsets.size(), " node offsets for ", ownership_.numCells(),
                " cells");
  for (const int first : cellNodeOffsets) {
    cellUnknownOffsets_.push_back(3 * static_cast<std::size_t>(first));
  }
}

void LocalMobilityPreconditioner::setCell(int cell, int firstNode, const elasticity::TangentStiffness& stiffness,
                                          std::vector<double> mobility, const adhesion::LoadStiffness* external)
{
  core::require(cell >= 0, "LocalMobilityPreconditioner: negative cell");
  core::require(mobility.size() == static_cast<std::size_t>(stiffness.numNodes()),
                "LocalMobilityPreconditioner: one mobility per node expected");
  if (cells_.size() <= static_cast<std::size_t>(cell)) {
    cells_.resize(static_cast<std::size_t>(cell) + 1);
  }
  CellBlock& block = cells_[static_cast<std::size_t>(cell)];
  const int n = 3 * stiffness.numNodes();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(stiffness.elements().size() * 18 * 18);
  const auto add = [&entries](int row, int column, double value) { entries.emplace_back(row, column, value); };
  stiffness.forEachEntry(add);
  if (external != nullptr) { // bonds on patches and tethers couple nodes of several elements
    external->forEachEntry(add);
  }
  SparseMatrix H(n, n);
  H.setFromTriplets(entries.begin(), entries.end()); // sums the element contributions
  // The factorisation's symbolic analysis is reused only for the very same pattern: bonds
  // that form and break change it, possibly keeping the number of entries.
  const bool samePattern =
      block.patternAnalysed && block.firstNode == firstNode && block.stiffness.rows() == n &&
      block.stiffness.nonZeros() == H.nonZeros() &&
      std::equal(H.outerIndexPtr(), H.outerIndexPtr() + n + 1, block.stiffness.outerIndexPtr()) &&
      std::equal(H.innerIndexPtr(), H.innerIndexPtr() + H.nonZeros(), block.stiffness.innerIndexPtr());
  block.firstNode = firstNode;
  block.stiffness = std::move(H);
  block.inverseMobility.resize(n);
  for (int k = 0; k < n; ++k) {
    block.inverseMobility[k] = 1.0 / mobility[static_cast<std::size_t>(k / 3)];
  }
  block.patternAnalysed = samePattern;
  approximationChanged();
}

void LocalMobilityPreconditioner::factorise(double shift)
{
  // A singular block on one rank stops the solve on every rank.
  ownership_.forEachOwnedCell([&](int cell) {
    if (static_cast<std::size_t>(cell) >= cells_.size() ||
        cells_[static_cast<std::size_t>(cell)].stiffness.rows() == 0) {
      return;
    }
    CellBlock& block = cells_[static_cast<std::size_t>(cell)];
    SparseMatrix A = shift * block.stiffness;
    A.diagonal() += block.inverseMobility; // H has every diagonal entry (a node couples to itself)
    A.makeCompressed();
    if (!block.ldlt) {
      block.ldlt = std::make_unique<Eigen::SimplicialLDLT<SparseMatrix>>();
    }
    if (!block.patternAnalysed) {
      block.ldlt->analyzePattern(A);
      block.patternAnalysed = true;
    }
    block.ldlt->factorize(A);
    block.lu.reset();
    if (block.ldlt->info() != Eigen::Success) {
      // An indefinite H (a membrane in compression) can defeat LDL^T without pivoting.
      block.lu = std::make_unique<Eigen::SparseLU<SparseMatrix>>();
      block.lu->compute(A);
      core::require<core::NumericalError>(block.lu->info() == Eigen::Success,
                                          "The preconditioner of the stiff stage solve is singular (shift ", shift,
                                          "): set 'Solver/Stiff/Preconditioner' to None.");
    }
  });
}

void LocalMobilityPreconditioner::solve(const double* x, double* z) const
{
  std::copy(x, x + map().getNodeNumElements(), z); // nodes of no cell, cells without a block: identity
  for (const CellBlock& block : cells_) {
    const auto n = block.stiffness.rows();
    if (n == 0) {
      continue;
    }
    const std::size_t first = 3 * static_cast<std::size_t>(block.firstNode);
    local_.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      local_[k] = block.inverseMobility[k] * x[first + static_cast<std::size_t>(k)];
    }
    solved_ = block.lu ? Eigen::VectorXd(block.lu->solve(local_)) : Eigen::VectorXd(block.ldlt->solve(local_));
    for (Eigen::Index k = 0; k < n; ++k) {
      z[first + static_cast<std::size_t>(k)] = solved_[k];
    }
  }
  shared_.assign(z, z + map().getNodeNumElements());
  ownership_.share(shared_, cellUnknownOffsets_);
  std::copy(shared_.begin(), shared_.end(), z);
}

} // namespace capsula::scene
