#include "capsula/operators/StageJacobian.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/Timers.hpp>

#include <sstream>
#include <utility>

namespace capsula::operators {

StageJacobian::StageJacobian(const StageSolverSettings& stage, const std::string& timerName,
                             std::string suggestedPreconditioner)
    : stage_(stage),
      suggestedPreconditioner_(std::move(suggestedPreconditioner)),
      lineariseTimer_(core::timer(timerName + ": linearise")),
      applyTimer_(core::timer(timerName + ": apply")),
      preconditionerTimer_(core::timer(timerName + ": preconditioner"))
{}

void StageJacobian::startSolver(Teuchos::RCP<const Tpetra::Map<>> map, Teuchos::RCP<StagePreconditioner> preconditioner)
{
  core::require(!solver_, "StageJacobian: startSolver called twice");
  preconditioner_ = std::move(preconditioner);
  SolverParameters gmres;
  gmres.restart = stage_.restart;
  gmres.maximumIterations = stage_.maximumIterations;
  solver_ = std::make_unique<StageSolver>(
      std::move(map), [this](const double* x, double* y) { apply(x, y); }, preconditioner_, gmres,
      static_cast<std::size_t>(stage_.recycledProducts));
  solver_->boundLargestError(stage_.largestErrorFactor);
}

void StageJacobian::linearise(double t, const std::vector<double>& y)
{
  Teuchos::TimeMonitor guard(*lineariseTimer_);
  solver_->newJacobian();
  freeze(t, y);
}

void StageJacobian::apply(const double* x, double* y)
{
  Teuchos::TimeMonitor guard(*applyTimer_);
  ++applications_;
  applyFrozen(x, y);
}

timeint::LinearSolveReport StageJacobian::solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                                                double residualRms)
{
  if (!preconditioner_.is_null()) {
    Teuchos::TimeMonitor guard(*preconditionerTimer_);
    preconditioner_->setShift(shift);
  }
  const StageSolveResult result = solver_->solve(shift, r, x, residualRms);
  timeint::LinearSolveReport report;
  report.converged = result.converged;
  report.iterations = result.iterations;
  report.residualRms = result.residualRms;
  return report;
}

std::string StageJacobian::settingsHint() const
{
  std::ostringstream hint;
  hint << "(" << operators::settingsHint(stage_);
  if (preconditioner_.is_null()) {
    hint << ", or set 'Solver/Stiff/Preconditioner' to '" << suggestedPreconditioner_ << "'";
  }
  hint << ")";
  return hint.str();
}

} // namespace capsula::operators
