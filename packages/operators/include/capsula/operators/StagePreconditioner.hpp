#pragma once
// A right preconditioner P ~ W of the stiff stage solves (StageSolver.hpp), W = I - shift J~,
// as the 3D scenes' (scene::LocalMobilityPreconditioner) and the 2D cell's
// (DenseStagePreconditioner) both are: an approximation of J~ factorised once per shift
// (setShift, before the solve), then P^-1 applied to whole, locally replicated vectors, so
// that every rank gets the same bits. This base holds what is common to them: the map, the
// shift bookkeeping (a new approximation or shift refactorises, the same one does not) and
// the Tpetra application Y = alpha P^-1 X + beta Y; a derived class factorises and solves.
#include <Teuchos_RCP.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <optional>
#include <string>
#include <vector>

namespace capsula::operators {

class StagePreconditioner : public Tpetra::Operator<double> {
public:
  using Map = Tpetra::Map<>;
  using MultiVector = Tpetra::MultiVector<double>;

  /// Factorises P = I - shift A for the current approximation A (nothing if neither the
  /// shift nor A has changed since the last factorisation).
  void setShift(double shift);

  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  bool hasTransposeApply() const override { return false; }
  /// Y = alpha P^-1 X + beta Y. Throws std::invalid_argument for a transpose, core::Error
  /// before the first setShift.
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override;

protected:
  /// `map`: locally replicated (throws core::Error otherwise); `name` for the messages.
  StagePreconditioner(Teuchos::RCP<const Map> map, std::string name);

  const Map& map() const { return *map_; }
  const std::string& name() const { return name_; }
  /// The approximation changed: the next setShift factorises, whatever its shift.
  void approximationChanged() { factorisedShift_.reset(); }

  /// Factorises P at `shift`. Throws core::NumericalError if P is singular.
  virtual void factorise(double shift) = 0;
  /// z = P^-1 x over the whole map (both of its size).
  virtual void solve(const double* x, double* z) const = 0;

private:
  Teuchos::RCP<const Map> map_;
  std::string name_;
  std::optional<double> factorisedShift_;
  mutable std::vector<double> solved_;
};

} // namespace capsula::operators
