#pragma once
// The matrix of a linearly implicit time step (timeint/LinearisedSystem.hpp),
//   W x = x - shift J~ x,
// applied matrix-free for Belos. J~ comes as an action on whole vectors (3 unknowns per
// node of the scene) whose result is the same on every rank; the work inside it (the
// layer potentials of the owned rows) is what the ranks share. The operator's map is
// locally replicated: Belos's inner products then need no reduction, so every rank, and
// every number of ranks, takes the same Krylov steps and gets the same bits.
#include <capsula/operators/JacobianProducts.hpp>

#include <Teuchos_RCP.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <functional>
#include <vector>

namespace capsula::operators {

class StageOperator final : public Tpetra::Operator<double> {
public:
  using Map = Tpetra::Map<>;
  using MultiVector = Tpetra::MultiVector<double>;
  /// y = J~ x for whole vectors (collective: every rank calls it with the same x).
  using Action = std::function<void(const double* x, double* y)>;

  /// `map` must be locally replicated (Tpetra::LocallyReplicated).
  StageOperator(Teuchos::RCP<const Map> map, Action jacobian);

  void setShift(double shift) { shift_ = shift; }
  double shift() const { return shift_; }

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }

  /// Y = alpha W X + beta Y (beta = 0 ignores what Y held). Throws std::invalid_argument
  /// for a transpose: J~ has no cheap transpose.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override;

  /// Keeps every product (x, J~ x) this operator makes in `products` (null: none).
  void keepProductsIn(JacobianProducts* products) { products_ = products; }

  /// Applications of J~ so far.
  long long applications() const { return applications_; }

private:
  Teuchos::RCP<const Map> map_;
  Action jacobian_;
  double shift_ = 0.0;
  JacobianProducts* products_ = nullptr;
  mutable std::vector<double> product_;
  mutable long long applications_ = 0;
};

} // namespace capsula::operators
