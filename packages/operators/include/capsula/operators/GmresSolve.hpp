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
                           const Teuchos::RCP<Tpetra::MultiVector<double>>& x, const SolverParameters& parameters);

/// The same with a right preconditioner M ~ A^-1 (null: none), by flexible GMRES: it
/// keeps the preconditioned vectors, so its residual estimate is that of the iterate
/// itself and no explicit residual A x - b is formed to confirm it (an application of A
/// saved per solve). `zeroInitialGuess`: x holds zeros, so the initial residual is b (one
/// more application saved). For solves that cost little more than those two.
GmresResult solveWithGmres(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                           const Teuchos::RCP<const Tpetra::Operator<double>>& M,
                           const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                           const Teuchos::RCP<Tpetra::MultiVector<double>>& x, const SolverParameters& parameters,
                           bool zeroInitialGuess = false);

} // namespace capsula::operators
