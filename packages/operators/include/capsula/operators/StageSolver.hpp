#pragma once
// Solves with the matrix of a linearly implicit step, W = I - shift J~ (StageOperator),
// for the stiff time integrators of the 3D scenes and the 2D tethered cell: Belos flexible
// GMRES with a right preconditioner, to an RMS residual target. J~ comes as an action on
// whole, locally replicated vectors: every rank takes the same Krylov steps and gets the
// same bits.
//
// The method is fixed, not 'Solver/Method' (which chooses the viscosity-ratio equation's).
// The preconditioner stays the same within a solve (its shift is set before each), so
// flexibility itself is not needed; what flexible GMRES brings is that it keeps the
// preconditioned vectors, so the residual it tests is that of its iterate and each solve
// stops on the RMS residual the integrator asks for without an application of W to confirm
// it (KrylovSolve.hpp). The other methods would test an estimate, or pay that application.
// 'Solver/Stiff' sets only the restart length, the iteration cap and how many products of
// J~ a step keeps (JacobianProducts.hpp): a solve starts from the least-residual
// combination of the products the step's earlier solves made, until newJacobian().
#include <capsula/operators/JacobianProducts.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/StageOperator.hpp>

#include <Teuchos_RCP.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Operator.hpp>

#include <vector>

namespace capsula::operators {

/// How one solve went.
struct StageSolveResult {
  bool converged = false;
  int iterations = 0;        ///< GMRES iterations
  bool recycled = false;     ///< started from the kept products of J~
  int errorChecks = 0;       ///< correction solves of boundLargestError's check
  double largestError = 0.0; ///< the last error estimate's largest coordinate (0 without a check)
  double residualRms = 0.0;  ///< achieved ||r - W x||_2 / sqrt(n)
};

class StageSolver {
public:
  /// On the locally replicated `map`, with J~ = `jacobian`, the preconditioner `M` ~ W^-1
  /// (null: none; its shift is the caller's to set before each solve) and the GMRES
  /// restart and iteration cap of `gmres` (its tolerance is set per solve); keeps up to
  /// `recycledProducts` products of J~ between newJacobian() calls (0: every solve starts
  /// afresh).
  StageSolver(Teuchos::RCP<const Tpetra::Map<>> map, StageOperator::Action jacobian,
              Teuchos::RCP<const Tpetra::Operator<double>> M, const SolverParameters& gmres,
              std::size_t recycledProducts = 0);

  // The stage operator keeps a pointer to products_: no copies, no moves.
  StageSolver(const StageSolver&) = delete;
  StageSolver& operator=(const StageSolver&) = delete;

  /// Checks each solve's error in the step controller's norm, the largest coordinate: once
  /// the RMS residual is reached, the error W^-1 (r - W x) is estimated, first by the
  /// preconditioner (M (r - W x), one application of W and M), and where that exceeds
  /// `factor` x residualRms by correction solves W d = r - W x to a tenth of that residual,
  /// which x takes, until |d|_max <= `factor` x residualRms (at most four; else the solve
  /// counts as failed). An RMS residual alone cannot see an error concentrated on a few
  /// coordinates, as W nearly singular gives it (docs/stiff-integration.md). 0: no check.
  void boundLargestError(double factor) { largestErrorFactor_ = factor; }

  /// J~ changed (a new step's linearisation): the kept products no longer apply.
  void newJacobian() { products_.clear(); }

  /// Solves W x = r to an RMS residual of at most `residualRms`; x's content on entry is
  /// the initial guess (all zeros saves an application of W; with kept products of J~, an
  /// all-zero x starts from their least-residual combination instead). A right-hand side
  /// already within the target gives x = 0 without an iteration (boundLargestError's check
  /// still applies to it).
  StageSolveResult solve(double shift, const std::vector<double>& r, std::vector<double>& x, double residualRms);

private:
  Teuchos::RCP<const Tpetra::Map<>> map_;
  Teuchos::RCP<StageOperator> stage_;
  Teuchos::RCP<const Tpetra::Operator<double>> preconditioner_;
  SolverParameters gmres_;
  JacobianProducts products_;
  std::vector<double> residual_; ///< r - W x0 of the recycled guess x0
  double largestErrorFactor_ = 0.0;

  /// The correction rounds of boundLargestError on a converged x.
  void checkLargestError(const std::vector<double>& r, std::vector<double>& x, double residualRms,
                         StageSolveResult& result);
};

} // namespace capsula::operators
