#include "capsula/operators/KrylovSolve.hpp"

#include "capsula/operators/KrylovMethod.hpp"

#include <capsula/core/Error.hpp>

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory.hpp>
#include <BelosSolverFactory_Tpetra.hpp>
#include <BelosTpetraAdapter.hpp>

#include <sstream>

namespace capsula::operators {

namespace {

using MV = Tpetra::MultiVector<double>;
using OP = Tpetra::Operator<double>;

KrylovResult solveProblem(const std::string& method, const Teuchos::RCP<Teuchos::ParameterList>& settings,
                          const Teuchos::RCP<Belos::LinearProblem<double, MV, OP>>& problem)
{
  Belos::SolverFactory<double, MV, OP> factory;
  const auto solver = factory.create(method, settings);
  solver->setProblem(problem);
  Belos::ReturnType status = Belos::Unconverged;
  try {
    status = solver->solve();
  } catch (const std::exception& e) {
    throw core::NumericalError("The Belos solver '" + method + "' failed: " + core::lastLineOf(e.what()));
  }
  KrylovResult result;
  result.converged = status == Belos::Converged;
  result.iterations = solver->getNumIters();
  result.residual = solver->achievedTol();
  return result;
}

} // namespace

KrylovResult solveLinearSystem(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                               const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                               const Teuchos::RCP<Tpetra::MultiVector<double>>& x, const SolverParameters& parameters)
{
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(A, x, b));
  problem->setProblem();
  return solveProblem(parameters.method, belosSettings(parameters, parameters.method, parameters.belos), problem);
}

KrylovResult solveWithFlexibleGmres(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                                    const Teuchos::RCP<const Tpetra::Operator<double>>& M,
                                    const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                                    const Teuchos::RCP<Tpetra::MultiVector<double>>& x,
                                    const SolverParameters& parameters, bool zeroInitialGuess)
{
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(A, x, b));
  if (!M.is_null()) {
    problem->setRightPrec(M);
  }
  if (zeroInitialGuess) {
    problem->setInitResVec(b);
  }
  problem->setProblem();
  const std::string method = M.is_null() ? "Block GMRES" : "Flexible GMRES";
  return solveProblem(method, belosSettings(parameters, method, Teuchos::ParameterList()), problem);
}

std::string stoppedShortMessage(const std::string& equation, const SolverParameters& parameters,
                                const KrylovResult& result)
{
  std::ostringstream text;
  if (parameters.cellBlockPreconditioner) {
    text << "Flexible GMRES ('Solver/Preconditioner' = " << kCellBlockPreconditioner << ")";
  } else {
    text << "'Solver/Method' = " << parameters.method;
  }
  text << " for " << equation << " stopped after " << result.iterations << " iterations at relative residual "
       << result.residual << " > 'Solver/Tolerance' = " << parameters.tolerance
       << ". Raise 'Solver/Maximum iterations' or 'Solver/Restart', relax 'Solver/Tolerance', or choose another "
          "'Solver/Method'.";
  if (parameters.belos.numParams() > 0) {
    text << " The entries of 'Solver/Belos' (";
    bool first = true;
    for (auto it = parameters.belos.begin(); it != parameters.belos.end(); ++it) {
      text << (first ? "" : ", ") << "'" << parameters.belos.name(it) << "'";
      first = false;
    }
    text << ") take precedence over those keys.";
  }
  return text.str();
}

} // namespace capsula::operators
