#pragma once
// Belos block GMRES (block size 1) on a matrix-free Tpetra operator, configured from
// SolverParameters: tolerance on ||b - A x|| / ||b||, restart length, iteration cap.
#include <capsula/operators/OperatorParameters.hpp>

#include <Teuchos_RCP.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

namespace capsula::operators {

struct GmresResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0; ///< achieved relative residual
};

/// Solves A x = b from the initial guess in x; x holds the result.
GmresResult solveWithGmres(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                           const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                           const Teuchos::RCP<Tpetra::MultiVector<double>>& x,
                           const SolverParameters& parameters);

} // namespace capsula::operators
