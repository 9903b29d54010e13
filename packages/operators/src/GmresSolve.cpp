#include "capsula/operators/GmresSolve.hpp"

#include <BelosBlockGmresSolMgr.hpp>
#include <BelosLinearProblem.hpp>
#include <BelosTpetraAdapter.hpp>

namespace capsula::operators {

namespace {

using Solver = Belos::BlockGmresSolMgr<double, Tpetra::MultiVector<double>, Tpetra::Operator<double>>;

Teuchos::RCP<Teuchos::ParameterList> gmresParameters(const SolverParameters& parameters)
{
  auto list = Teuchos::rcp(new Teuchos::ParameterList);
  list->set("Convergence Tolerance", parameters.tolerance);
  list->set("Num Blocks", parameters.restart);
  list->set("Maximum Iterations", parameters.maximumIterations);
  list->set("Maximum Restarts", parameters.maximumIterations / parameters.restart + 1);
  // Relative to ||b||, so that a warm start does not change what "converged" means.
  list->set("Implicit Residual Scaling", "Norm of RHS");
  list->set("Explicit Residual Scaling", "Norm of RHS");
  list->set("Verbosity", Belos::Errors + Belos::Warnings);
  return list;
}

GmresResult finish(Solver& solver)
{
  const Belos::ReturnType status = solver.solve();
  GmresResult result;
  result.converged = status == Belos::Converged;
  result.iterations = solver.getNumIters();
  result.residual = solver.achievedTol();
  return result;
}

} // namespace

GmresResult solveWithGmres(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                           const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                           const Teuchos::RCP<Tpetra::MultiVector<double>>& x, const SolverParameters& parameters)
{
  using MV = Tpetra::MultiVector<double>;
  using OP = Tpetra::Operator<double>;
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(A, x, b));
  problem->setProblem();
  auto list = gmresParameters(parameters);
  Belos::BlockGmresSolMgr<double, MV, OP> solver(problem, list);
  return finish(solver);
}

GmresResult solveWithGmres(const Teuchos::RCP<const Tpetra::Operator<double>>& A,
                           const Teuchos::RCP<const Tpetra::Operator<double>>& M,
                           const Teuchos::RCP<const Tpetra::MultiVector<double>>& b,
                           const Teuchos::RCP<Tpetra::MultiVector<double>>& x, const SolverParameters& parameters,
                           bool zeroInitialGuess)
{
  using MV = Tpetra::MultiVector<double>;
  using OP = Tpetra::Operator<double>;
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(A, x, b));
  if (!M.is_null()) {
    problem->setRightPrec(M);
  }
  if (zeroInitialGuess) {
    problem->setInitResVec(b);
  }
  problem->setProblem();
  auto list = gmresParameters(parameters);
  list->set("Flexible Gmres", !M.is_null());
  Belos::BlockGmresSolMgr<double, MV, OP> solver(problem, list);
  return finish(solver);
}

} // namespace capsula::operators
