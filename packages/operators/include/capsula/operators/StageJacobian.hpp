#pragma once
// The Jacobian of the velocity a stiff time integrator needs (timeint::LinearisedSystem),
// as the 3D scenes (scene::VelocityJacobian) and the 2D cell (scene2d::VelocityJacobian2D)
// both form it: dx/dt = u(x) linearised as
//
//   J~ v = P [ a_g S(x_n)[K v] + b_g grad u_inf . v ]   (per node g),
//
// frozen at the step's start x_n, with K v the derivative of the membrane load, S the
// single layer of the frozen geometry, a_g = -1 / (4 pi (1 + lambda) Ca) in 3D (eq 3.38)
// and -1 / (2 pi (1 + lambda) Ca) in 2D (eq A.35), b_g = 2 / (1 + lambda) and P the stage
// constraints. The derived class knows K, S and P (freeze, applyFrozen); this base holds
// what both do alike: the solves with W = I - shift J~ by Belos GMRES on a locally
// replicated map (StageSolver) with a right preconditioner whose shift it sets before each
// solve (StagePreconditioner), the count of applications, the timers, the hint at the keys
// to change when a solve fails, and the sum of J~'s two terms (combineWithFlowGradient).
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/StagePreconditioner.hpp>
#include <capsula/operators/StageSolver.hpp>
#include <capsula/operators/StageSolverParameters.hpp>
#include <capsula/timeint/LinearisedSystem.hpp>

#include <Eigen/Core>
#include <Teuchos_RCP.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_Map.hpp>

#include <memory>
#include <string>
#include <vector>

namespace capsula::operators {

/// y_i = a(g) s_i + b(g) (G(g) x_g)_i for every node g of D unknowns: J~'s single-layer term
/// s and the background flow's gradient at the node, G(g) (a D x D matrix), acting on x,
/// weighted per node (see above).
template <int D, class FlowGradient, class SingleLayerWeight, class FlowWeight>
void combineWithFlowGradient(const FlowGradient& gradient, const SingleLayerWeight& a, const FlowWeight& b,
                             std::size_t nodes, const double* x, const std::vector<double>& s, double* y)
{
  for (std::size_t g = 0; g < nodes; ++g) {
    const Eigen::Matrix<double, D, D>& G = gradient(g);
    const double* xg = x + D * g;
    for (int i = 0; i < D; ++i) {
      double flow = G(i, 0) * xg[0];
      for (int j = 1; j < D; ++j) {
        flow += G(i, j) * xg[j];
      }
      y[D * g + i] = a(g) * s[D * g + i] + b(g) * flow;
    }
  }
}

class StageJacobian : public timeint::LinearisedSystem {
public:
  /// Freezes J~ at (t, y) (freeze) and drops the products of the previous J~.
  void linearise(double t, const std::vector<double>& y) final;
  /// Sets the preconditioner's shift, then solves W x = r by GMRES (StageSolver::solve).
  timeint::LinearSolveReport solve(double shift, const std::vector<double>& r, std::vector<double>& x,
                                   double residualRms) final;
  /// "(<the stage keys>[, or set 'Solver/Stiff/Preconditioner' to '<suggested>'])".
  std::string settingsHint() const final;

  /// y = J~ x at the last linearisation (whole vectors). Collective.
  void apply(const double* x, double* y);
  /// Applications of J~ so far (each one single-layer evaluation).
  long long applications() const { return applications_; }

  const StageSolverSettings& stageSettings() const { return stage_; }

protected:
  /// `stage`: the 'Solver/Stiff' keys of the solves; `timerName`: the prefix of the timers
  /// ("<timerName>: linearise", ": apply", ": preconditioner"); `suggestedPreconditioner`:
  /// the 'Solver/Stiff/Preconditioner' value settingsHint suggests when there is none.
  StageJacobian(const StageSolverSettings& stage, const std::string& timerName, std::string suggestedPreconditioner);

  /// Builds the stage solver on the locally replicated `map` with `preconditioner` (null:
  /// none). The derived constructor calls it once.
  void startSolver(Teuchos::RCP<const Tpetra::Map<>> map, Teuchos::RCP<StagePreconditioner> preconditioner);

  /// Freezes J~ (and the preconditioner's approximation of it) at (t, y).
  virtual void freeze(double t, const std::vector<double>& y) = 0;
  /// y = J~ x at the frozen state.
  virtual void applyFrozen(const double* x, double* y) = 0;

private:
  StageSolverSettings stage_;
  std::string suggestedPreconditioner_;
  Teuchos::RCP<StagePreconditioner> preconditioner_;
  std::unique_ptr<StageSolver> solver_; // GMRES on W
  long long applications_ = 0;
  Teuchos::RCP<Teuchos::Time> lineariseTimer_, applyTimer_, preconditionerTimer_;
};

} // namespace capsula::operators
