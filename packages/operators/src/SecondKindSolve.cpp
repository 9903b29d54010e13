#include "capsula/operators/SecondKindSolve.hpp"

#include <capsula/core/Error.hpp>

#include <Teuchos_Array.hpp>
#include <Tpetra_MultiVector.hpp>

namespace capsula::operators {

SecondKindSolution solveSecondKind(SecondKindEquation equation, const std::vector<double>& rhs,
                                   const SolverParameters& solver, const double* initialGuess,
                                   WarmStartHistory* history,
                                   const Teuchos::RCP<const Tpetra::Operator<double>>& preconditioner)
{
  const NodeDistribution& distribution = equation.distribution;
  const auto width = static_cast<std::size_t>(distribution.unknownsPerNode());
  const std::size_t firstUnknown = width * static_cast<std::size_t>(distribution.firstOwnedNode());
  std::vector<double> globalRhs, guess;
  if (history) { // every rank forms the same guess from the same global vectors
    globalRhs = distribution.gather(rhs);
    if (!history->empty() && history->length() != globalRhs.size()) {
      *history = WarmStartHistory(history->depth()); // another mesh: its solutions do not apply
    }
    guess = history->initialGuess(globalRhs);
    initialGuess = guess.data();
  }
  using MV = Tpetra::MultiVector<double>;
  const auto map = distribution.map();
  auto b = Teuchos::rcp(new MV(map, 1));
  auto x = Teuchos::rcp(new MV(map, 1));
  {
    auto bData = b->getDataNonConst(0);
    auto xData = x->getDataNonConst(0);
    for (std::size_t k = 0; k < rhs.size(); ++k) {
      bData[k] = rhs[k];
      xData[k] = initialGuess ? initialGuess[firstUnknown + k] : rhs[k];
    }
  }
  SecondKindSolution solution;
  Teuchos::Array<double> norm(1);
  b->norm2(norm());
  if (norm[0] == 0.0) {
    solution.velocities.assign(width * static_cast<std::size_t>(distribution.numNodes()), 0.0);
    return solution;
  }
  auto A = Teuchos::rcp(new SecondKindOperator(map, std::move(equation.doubleLayer), std::move(equation.densityScale),
                                               std::move(equation.rowScale), distribution.unknownsPerNode()));
  solution.krylov = preconditioner.is_null() ? solveLinearSystem(A, b, x, solver)
                                             : solveWithFlexibleGmres(A, preconditioner, b, x, solver);
  core::require<core::NumericalError>(solution.krylov.converged,
                                      stoppedShortMessage(equation.name, solver, solution.krylov));
  const auto xData = x->getData(0);
  solution.velocities = distribution.gather(std::vector<double>(xData.begin(), xData.end()));
  if (history) {
    history->add(std::move(globalRhs), solution.velocities);
  }
  return solution;
}

} // namespace capsula::operators
