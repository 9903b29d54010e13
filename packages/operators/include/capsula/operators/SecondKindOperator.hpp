#pragma once
// The left-hand side of the boundary-integral equation when some viscosity ratio is not
// 1 (thesis eq 3.15, Section 3.8), applied matrix-free for Belos:
//   (A u)(x_t) = u(x_t) - rowScale_t * DL[densityScale . u](x_t),
// DL the double layer with singularity subtraction at the owned nodes, densityScale the
// factor (1 - lambda_d) of the cell each node belongs to, rowScale_t = 1 / (4 pi (1 + lambda_c))
// for the cell of target t. apply() gathers the distributed u into a locally replicated
// copy (every row integrates over every node) with an Import built once.
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
  /// Writes the double layer of `density` (3 per node, all nodes) at the owned nodes
  /// (3 per owned node, in map order).
  using DoubleLayerRows = std::function<void(const double* density, double* ownedRows)>;

  /// `map` holds 3 unknowns per node (GID 3 g + i). densityScale: one factor per node of
  /// the whole scene; rowScale: one factor per owned node.
  SecondKindOperator(Teuchos::RCP<const Map> map, DoubleLayerRows doubleLayer,
                     std::vector<double> densityScale, std::vector<double> rowScale);

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }

  /// Y = alpha A X + beta Y (beta = 0 ignores what Y held). Throws std::invalid_argument
  /// for a transpose: A is not symmetric and has no cheap transpose.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override;

  /// Applications of A so far (each one double-layer evaluation).
  int applications() const { return applications_; }

private:
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<const Tpetra::Import<>> gather_;
  DoubleLayerRows doubleLayer_;
  std::vector<double> densityScale_;
  std::vector<double> rowScale_;
  mutable std::vector<double> density_, rows_;
  mutable int applications_ = 0;
  Teuchos::RCP<Teuchos::Time> timer_; // "Double-layer application": its count is the GMRES work
};

} // namespace capsula::operators
