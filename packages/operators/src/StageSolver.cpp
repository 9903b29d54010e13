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
  stage_->setShift(shift);
  if (norm <= target) { // x = 0 is already close enough
    x.assign(n, 0.0);
    result.converged = true;
    result.residualRms = norm / rootN;
    checkLargestError(r, x, residualRms, result);
    return result;
  }
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
      checkLargestError(r, x, residualRms, result);
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
  if (result.converged) {
    checkLargestError(r, x, residualRms, result);
  }
  return result;
}

void StageSolver::checkLargestError(const std::vector<double>& r, std::vector<double>& x, double residualRms,
                                    StageSolveResult& result)
{
  if (largestErrorFactor_ <= 0.0) {
    return;
  }
  // The error of x is W^-1 (r - W x). The preconditioner M ~ W^-1 estimates it for one
  // application of each; only where that estimate exceeds the bound do correction solves to
  // a tenth of the residual they correct (each estimating the error to about 10%) follow,
  // the solution taking each correction. More than four mean W is too near singular for this
  // step (the step is then rejected and retried smaller, W closer to I).
  constexpr double kCorrectionReduction = 0.1;
  constexpr int kMaximumCorrections = 4;
  using MV = Tpetra::MultiVector<double>;
  const double bound = largestErrorFactor_ * residualRms;
  auto current = Teuchos::rcp(new MV(map_, 1));
  auto rhs = Teuchos::rcp(new MV(map_, 1));
  std::copy(r.begin(), r.end(), rhs->getDataNonConst(0).getRawPtr());
  auto residual = Teuchos::rcp(new MV(map_, 1));
  auto correction = Teuchos::rcp(new MV(map_, 1));
  const auto largestEntry = [](const MV& v) {
    double largest = 0.0;
    for (const double e : v.getData(0)) {
      largest = std::max(largest, std::abs(e));
    }
    return largest;
  };
  SolverParameters parameters = gmres_;
  parameters.tolerance = kCorrectionReduction;
  for (int round = 0; round <= kMaximumCorrections; ++round) {
    std::copy(x.begin(), x.end(), current->getDataNonConst(0).getRawPtr());
    stage_->apply(*current, *residual);
    residual->update(1.0, *rhs, -1.0);    // r - W x
    if (largestEntry(*residual) == 0.0) { // x solves W x = r exactly
      result.largestError = 0.0;
      result.converged = true;
      return;
    }
    if (round == 0 && !preconditioner_.is_null()) {
      preconditioner_->apply(*residual, *correction);
      result.largestError = largestEntry(*correction);
      if (result.largestError <= bound) {
        return;
      }
    }
    if (round == kMaximumCorrections) {
      break;
    }
    correction->putScalar(0.0);
    const KrylovResult solved = solveWithFlexibleGmres(stage_, preconditioner_, residual, correction, parameters, true);
    ++result.errorChecks;
    result.iterations += solved.iterations;
    const auto d = correction->getData(0);
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] += d[i];
    }
    result.largestError = largestEntry(*correction);
    if (solved.converged && result.largestError <= bound) {
      return;
    }
  }
  result.converged = false;
}

} // namespace capsula::operators
