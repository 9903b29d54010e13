#pragma once
// The solve of the boundary-integral equation of the second kind when a viscosity ratio is
// not 1, in 2D (thesis eq A.35) and 3D (eq 3.15) alike:
//   u - rowScale DL[densityScale u] = rhs
// (SecondKindOperator.hpp) for the velocities u of every node, from the right-hand side's
// owned rows. The Krylov method of 'Solver/Method', or flexible GMRES with a right
// preconditioner (the cell blocks, CellBlockPreconditioner.hpp). The start: the caller's
// guess, or the warm start's least-squares combination of the last solutions
// (WarmStartHistory.hpp, which then gets the solved pair), or else the right-hand side.
// A zero right-hand side has the solution 0 (the homogeneous equation has only u = 0 for
// lambda > 0) without a solve.
#include <capsula/operators/KrylovSolve.hpp>
#include <capsula/operators/NodeDistribution.hpp>
#include <capsula/operators/OperatorParameters.hpp>
#include <capsula/operators/SecondKindOperator.hpp>
#include <capsula/operators/WarmStartHistory.hpp>

#include <Teuchos_RCP.hpp>
#include <Tpetra_Operator.hpp>

#include <string>
#include <vector>

namespace capsula::operators {

/// The equation: the double layer's rows, the scales and where the unknowns live.
struct SecondKindEquation {
  const NodeDistribution& distribution;            ///< the rows and their unknowns per node
  SecondKindOperator::DoubleLayerRows doubleLayer; ///< DL of a density at the owned nodes
  std::vector<double> densityScale;                ///< per node of the whole problem (empty: 1)
  std::vector<double> rowScale;                    ///< per owned node (0: the row is u = rhs)
  std::string name;                                ///< "the viscosity-ratio equation", for errors
};

struct SecondKindSolution {
  std::vector<double> velocities; ///< every node's, on every rank
  KrylovResult krylov;            ///< iterations 0 for a zero right-hand side
};

/// Solves `equation` for the owned rows `rhs` (collective). `initialGuess` (every node's
/// unknowns) or `history` may be null; a non-null `preconditioner` selects flexible GMRES.
/// Throws core::NumericalError naming the equation and the keys that limit the solve if it
/// stops short.
SecondKindSolution solveSecondKind(SecondKindEquation equation, const std::vector<double>& rhs,
                                   const SolverParameters& solver, const double* initialGuess,
                                   WarmStartHistory* history,
                                   const Teuchos::RCP<const Tpetra::Operator<double>>& preconditioner = Teuchos::null);

} // namespace capsula::operators
