#pragma once
// Belos Krylov solves on matrix-free Tpetra operators, the solver manager made by
// Belos::SolverFactory from its name. The viscosity-ratio equation takes the method and the
// settings of the deck's 'Solver' list (KrylovMethod.hpp); the stages of the stiff methods
// take flexible GMRES with their preconditioner.
#include <capsula/operators/OperatorParameters.hpp>

#include <Teuchos_RCP.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>

#include <string>

namespace capsula::operators {

struct KrylovResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0; ///< achieved relative residual, as the method measures it
};

/// Solves A x = b from the initial guess in x by parameters.method with
/// belosSettings(parameters, parameters.method, parameters.belos); x holds the result.
/// Throws core::NumericalError if Belos gives up with an exception (a breakdown).
KrylovResult solveLinearSystem(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                               const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                               const Teuchos::RCP<Tpetra::MultiVector<double>>& x, const SolverParameters& parameters);

/// The same with a right preconditioner M ~ A^-1 (null: none, and then Block GMRES) by
/// flexible GMRES, whatever parameters.method and parameters.belos say: only the tolerance,
/// restart length and iteration cap of `parameters` apply. Flexible GMRES keeps the
/// preconditioned vectors, so its residual estimate is that of the iterate itself and no
/// explicit residual A x - b is formed to confirm it (an application of A saved per solve).
/// `zeroInitialGuess`: x holds zeros, so the initial residual is b (one more application
/// saved). For solves that cost little more than those two.
KrylovResult solveWithFlexibleGmres(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                                    const Teuchos::RCP<const Tpetra::Operator<double>>& M,
                                    const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                                    const Teuchos::RCP<Tpetra::MultiVector<double>>& x,
                                    const SolverParameters& parameters, bool zeroInitialGuess = false);

/// Why a solve of `equation` by solveLinearSystem stopped short, naming the keys that set
/// its limits and, when 'Solver/Belos' has entries, that they take precedence.
std::string stoppedShortMessage(const std::string& equation, const SolverParameters& parameters,
                                const KrylovResult& result);

} // namespace capsula::operators
