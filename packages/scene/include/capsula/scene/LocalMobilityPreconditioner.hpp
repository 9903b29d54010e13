#pragma once
// The preconditioner of the stiff stage solves (VelocityJacobian.hpp). The stage matrix
// is W = I + shift c S M^-1 H (c = 1 / (4 pi (1 + lambda) Ca), S the single layer, M the
// mass matrix, H the membrane's tangent stiffness). Its stiff part is the product of the
// nonlocal single layer with the sparse stiffness. Here S M^-1 is replaced by a diagonal
// local mobility: node i, loaded by a force F spread over its share A_i of the area (a
// disc of radius R_i = sqrt(A_i / pi)), moves at c beta F / R_i (the single layer of a
// uniform disc load is 2 F / R normal and 3 F / R tangential at the centre: beta ~ 2.5).
// The result,
//     P = I + shift B H,   B = diag(b_i),  b_i = c beta / R_i,
// is sparse with H's pattern, block diagonal over the cells, and its inverse is applied
// through the symmetric matrix B^-1 + shift H: P z = x  <=>  (B^-1 + shift H) z = B^-1 x,
// factorised per cell (sparse LDL^T, sparse LU where that fails) once per shift.
//
// On the fast, grid-scale membrane modes S acts locally and P is close to W; the smooth
// modes, where the nonlocal S is larger than any local mobility, are left to GMRES, a few
// iterations. A rank factorises and solves the blocks of the cells it owns
// (CellOwnership.hpp) and the others' parts of z come from their owners, so every rank
// ends with the whole (replicated) z (the shift bookkeeping and the application are
// operators::StagePreconditioner's). The stiffness of the forces
// from outside (bonds, wall contact: adhesion LoadStiffness.hpp) adds to H.
#include <capsula/adhesion/LoadStiffness.hpp>
#include <capsula/elasticity/TangentStiffness.hpp>
#include <capsula/operators/StagePreconditioner.hpp>
#include <capsula/scene/CellOwnership.hpp>

#include <Eigen/Sparse>

#include <memory>
#include <vector>

namespace capsula::scene {

class LocalMobilityPreconditioner final : public operators::StagePreconditioner {
public:
  /// `map`: locally replicated, 3 unknowns per node of the scene; `cellNodeOffsets`: the
  /// first node of each cell and, last, the number of nodes.
  LocalMobilityPreconditioner(Teuchos::RCP<const Map> map, CellOwnership ownership, std::vector<int> cellNodeOffsets);

  /// The cell whose nodes start at `firstNode`: its stiffness H (plus `external`, if any,
  /// numbered within the cell) and mobilities b (one per node). Replaces what an earlier
  /// call gave for the same cell. Called by the cell's owner; a cell without a block
  /// keeps z = x.
  void setCell(int cell, int firstNode, const elasticity::TangentStiffness& stiffness, std::vector<double> mobility,
               const adhesion::LoadStiffness* external = nullptr);

private:
  /// Factorises B^-1 + shift H of every cell.
  void factorise(double shift) override;
  void solve(const double* x, double* z) const override;

  using SparseMatrix = Eigen::SparseMatrix<double>;
  struct CellBlock {
    int firstNode = 0;
    SparseMatrix stiffness;          // H
    Eigen::VectorXd inverseMobility; // B^-1, 3 entries per node
    std::unique_ptr<Eigen::SimplicialLDLT<SparseMatrix>> ldlt;
    std::unique_ptr<Eigen::SparseLU<SparseMatrix>> lu; // where LDL^T fails
    bool patternAnalysed = false;
  };

  CellOwnership ownership_;
  std::vector<std::size_t> cellUnknownOffsets_; // 3 per node: where each cell's part of z begins
  std::vector<CellBlock> cells_;                // empty (no rows) where the cell is another rank's
  mutable Eigen::VectorXd local_, solved_;
  mutable std::vector<double> shared_;
};

} // namespace capsula::scene
