#pragma once
// The left-hand side of the 2D boundary-integral equation when lambda != 1 (thesis
// eq A.35, App. A.7), applied matrix-free for Belos:
//   (A u)(x_t) = u(x_t) - c DL[u](x_t),   c = (1 - lambda) / (2 pi (1 + lambda)),
// DL the subtracted double layer at the owned nodes (LayerPotentials2D), and
//   (A u)(x_t) = u(x_t)
// at a node whose velocity is prescribed (the tether: its right-hand side is the
// prescribed velocity, 0). apply() gathers the distributed u into a locally replicated
// copy with an Import built once (every row integrates over every node): the same pattern
// as the 3D SecondKindOperator, with 2 unknowns per node.
#include <Teuchos_RCP.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <functional>
#include <vector>

namespace capsula::operators {

class SecondKindOperator2D final : public Tpetra::Operator<double> {
public:
  using Map = Tpetra::Map<>;
  using MultiVector = Tpetra::MultiVector<double>;
  /// Writes DL of `density` (2 per node, all nodes) at the owned nodes (2 per owned node).
  using DoubleLayerRows = std::function<void(const double* density, double* ownedRows)>;

  /// `map`: 2 unknowns per node (GID 2 g + i), whole nodes per rank. `fixedRow` holds one
  /// flag per owned node: true where the velocity is prescribed.
  SecondKindOperator2D(Teuchos::RCP<const Map> map, DoubleLayerRows doubleLayer, double coefficient,
                       std::vector<char> fixedRow);

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }

  /// Y = alpha A X + beta Y (beta = 0 ignores what Y held). Throws std::invalid_argument
  /// for a transpose.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override;

  /// Applications of A so far (each one double-layer evaluation).
  int applications() const { return applications_; }

private:
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<const Tpetra::Import<>> gather_;
  DoubleLayerRows doubleLayer_;
  double coefficient_;
  std::vector<char> fixedRow_;
  mutable std::vector<double> density_, rows_;
  mutable int applications_ = 0;
};

} // namespace capsula::operators
