#include "capsula/operators/StageSolver.hpp"

#include <capsula/operators/KrylovSolve.hpp>

#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <cmath>

namespace capsula::operators {

StageSolver::StageSolver(Teuchos::RCP<const Tpetra::Map<>> map, StageOperator::Action jacobian,
                         Teuchos::RCP<const Tpetra::Operator<double>> M, const SolverParameters& gmres,
                         std::size_t recycledProducts)
    : map_(std::move(map)),
      stage_(Teuchos::rcp(new StageOperator(map_, std::move(jacobian)))),
      preconditioner_(std::move(M)),
      gmres_(gmres),
      products_(recycledProducts)
{
  if (recycledProducts > 0) {
    stage_->keepProductsIn(&products_);
  }
}

StageSolveResult StageSolver::solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                                    double residualRms)
{
  StageSolveResult result;
  const std::size_t n = r.size();
  const double rootN = std::sqrt(static_cast<double>(n));
  double norm = 0.0;
  for (const double v : r) {
    norm += v * v;
  }
  norm = std::sqrt(norm);
  const double target = residualRms * rootN;
  if (norm <= target) { // x = 0 is already close enough
    x.assign(n, 0.0);
    result.converged = true;
    result.residualRms = norm / rootN;
    return result;
  }
  stage_->setShift(shift);
  const bool zeroGuess = std::all_of(x.begin(), x.end(), [](double v) { return v == 0.0; });
  // With kept products, solve W d = r - W x0 for the correction d of the recycled guess x0.
  std::vector<double> guess;
  double initial = norm;
  const std::vector<double>* rhs = &r;
  if (zeroGuess && products_.size() > 0) {
    initial = products_.minimalResidualGuess(shift, r, guess, residual_);
    result.recycled = true;
    if (initial <= target) {
      x = guess;
      result.converged = true;
      result.residualRms = initial / rootN;
      return result;
    }
    rhs = &residual_;
  }
  using MV = Tpetra::MultiVector<double>;
  auto b = Teuchos::rcp(new MV(map_, 1));
  auto solution = Teuchos::rcp(new MV(map_, 1));
  std::copy(rhs->begin(), rhs->end(), b->getDataNonConst(0).getRawPtr());
  std::copy(x.begin(), x.end(), solution->getDataNonConst(0).getRawPtr());
  SolverParameters parameters = gmres_;
  parameters.tolerance = std::max(target / initial, 1e-14);
  const KrylovResult gmres = solveWithFlexibleGmres(stage_, preconditioner_, b, solution, parameters, zeroGuess);
  const auto xData = solution->getData(0);
  x.assign(xData.begin(), xData.end());
  for (std::size_t i = 0; i < guess.size(); ++i) {
    x[i] += guess[i];
  }
  result.converged = gmres.converged;
  result.iterations = gmres.iterations;
  result.residualRms = gmres.residual * initial / rootN;
  return result;
}

} // namespace capsula::operators
