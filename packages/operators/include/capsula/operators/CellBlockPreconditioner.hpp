#pragma once
// A right preconditioner of the viscosity-ratio equation (SecondKindOperator.hpp) for many
// cells ('Solver/Preconditioner' = "Cell blocks"): block Jacobi over the cells,
//   M = blockdiag_c P_c^-1,   P_c = I - s_c D_cc,   s_c = (1 - lambda_c) / (4 pi (1 + lambda_c)),
// D_cc the double layer of cell c on its own nodes (LayerPotentials::cellDoubleLayerBlock).
// A cell at lambda = 1 has s_c = 0 and an identity block.
//
// Why it pays: the spread of A = I - s D that GMRES iterates on lies within each cell (on a
// cell's rigid-body motions D u = -4 pi u, so A u = 2 / (1 + lambda) u; on its smooth
// deformations A is near I), and the cells couple only through the decaying field of the
// others; with P_c inverted, what GMRES sees is I plus that coupling (and, for a periodic
// kernel, a cell's images). Flexible GMRES takes it on the right, so the stopping test stays
// on ||b - A u|| / ||b||.
//
// Each P_c is dense (3 n_c unknowns), held and LU-factorised (partial pivoting) in single
// precision: it only steers the iteration, and the solution's accuracy is the tolerance's.
// Each block is held by one rank: the blocks go to the ranks in contiguous runs balanced by
// their size, whichever ranks own the cell's rows (a suspension's cells without a block,
// platelets at lambda = 1 say, would otherwise leave the ranks that own their rows with
// fewer blocks to store and factorise). The ranks that own a cell's rows compute them; where
// they are not the holder, each sends its rows, zero elsewhere, in a sum reduced onto the
// holder, one cell at a time. So the holder factorises the same bits whatever the number of
// ranks. apply() gathers X into a locally replicated copy (an Import built once), each rank
// solves the blocks it holds, a sum of the zero-padded solutions hands them to every rank,
// and each keeps the rows it owns.
#include <Eigen/Core>
#include <Eigen/LU>

#include <Teuchos_RCP.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <functional>
#include <utility>
#include <vector>

namespace capsula::operators {

class CellBlockPreconditioner final : public Tpetra::Operator<double> {
public:
  using Map = Tpetra::Map<>;
  using MultiVector = Tpetra::MultiVector<double>;
  /// Writes D_cc's rows of the nodes this rank owns in cell c (3 per node, row-major over
  /// the cell's 3 n_c columns) into `rows`; returns the number of those nodes. Called once
  /// per cell with s_c != 0 that the rank owns nodes of.
  using CellRows = std::function<int(int cell, std::vector<double>& rows)>;

  /// `map`: 3 unknowns per node, whole nodes, contiguous on each rank (NodeDistribution).
  /// cellNodeOffsets: the first node of each cell and, last, the number of nodes; cellScale:
  /// s_c per cell (0: identity). Assembles and factorises every block; collective. Throws
  /// core::NumericalError naming the cell if a block is singular.
  CellBlockPreconditioner(Teuchos::RCP<const Map> map, std::vector<int> cellNodeOffsets, std::vector<double> cellScale,
                          const CellRows& rowsOf);

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }

  /// Y = alpha M X + beta Y (beta = 0 ignores what Y held). Throws std::invalid_argument for
  /// a transpose.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override;

  /// The cells whose blocks this rank holds.
  int heldBlocks() const { return static_cast<int>(blocks_.size()); }

private:
  struct Block {
    int cell;
    int firstNode, numNodes;
    Eigen::PartialPivLU<Eigen::MatrixXf> lu;
  };

  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<const Tpetra::Import<>> gather_;
  std::vector<Block> blocks_;
  std::vector<std::pair<std::size_t, std::size_t>> blockUnknowns_; // every block's [first, end) unknowns, in order
  int firstOwnedNode_ = 0;
  int numOwnedNodes_ = 0;
  Teuchos::RCP<Teuchos::Time> timer_; // "Cell-block preconditioner": its applications
};

} // namespace capsula::operators
