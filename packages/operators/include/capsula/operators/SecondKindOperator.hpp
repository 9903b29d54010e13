#pragma once
// The left-hand side of the boundary-integral equation when a viscosity ratio is not 1,
// applied matrix-free for Belos, in 2D (thesis eq A.35, App. A.7) and 3D (eq 3.15,
// Section 3.8) alike:
//   (A u)(x_t) = u(x_t) - rowScale_t * DL[densityScale . u](x_t),
// DL the double layer with singularity subtraction at the owned nodes, densityScale the
// factor of the node each density value belongs to, rowScale the factor of the row's node:
//   3D  densityScale = 1 - lambda_d of the node's cell, rowScale = 1 / (4 pi (1 + lambda_c)),
//   2D  no densityScale (1), rowScale = (1 - lambda) / (2 pi (1 + lambda)), and 0 at a node
//       whose velocity is prescribed (the tether: (A u)(x_t) = u(x_t), right-hand side 0).
// A row scale of exactly 0 leaves the row the identity. apply() gathers the distributed u
// into a locally replicated copy (every row integrates over every node) with an Import
// built once. `unknownsPerNode` (2 or 3) is the stride of the map: GID d g + i.
#include <Teuchos_RCP.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <functional>
#include <vector>

namespace capsula::operators {

class SecondKindOperator final : public Tpetra::Operator<double> {
public:
  using Map = Tpetra::Map<>;
  using MultiVector = Tpetra::MultiVector<double>;
  /// Writes the double layer of `density` (unknownsPerNode per node, all nodes) at the
  /// owned nodes (unknownsPerNode per owned node, in map order).
  using DoubleLayerRows = std::function<void(const double* density, double* ownedRows)>;

  /// `map` holds `unknownsPerNode` unknowns per node, whole nodes per rank. densityScale:
  /// one factor per node of the whole problem, or empty for none; rowScale: one factor per
  /// owned node.
  SecondKindOperator(Teuchos::RCP<const Map> map, DoubleLayerRows doubleLayer, std::vector<double> densityScale,
                     std::vector<double> rowScale, int unknownsPerNode = 3);

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }

  /// Y = alpha A X + beta Y (beta = 0 ignores what Y held). Throws std::invalid_argument
  /// for a transpose: A is not symmetric and has no cheap transpose.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override;

  /// Applications of A so far (each one double-layer evaluation).
  int applications() const { return applications_; }

private:
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<const Tpetra::Import<>> gather_;
  DoubleLayerRows doubleLayer_;
  std::vector<double> densityScale_;
  std::vector<double> rowScale_;
  std::size_t unknownsPerNode_;
  mutable std::vector<double> density_, rows_;
  mutable int applications_ = 0;
  Teuchos::RCP<Teuchos::Time> timer_; // "Double-layer application": its count is the GMRES work
};

} // namespace capsula::operators
