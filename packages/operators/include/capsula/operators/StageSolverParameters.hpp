#pragma once
// The keys of a deck's "Solver/Stiff" sublist that the stage solves themselves read
// (StageSolver.hpp), shared by the 3D scenes and tether2d; each app's Jacobian declares its
// preconditioner and quadrature keys next to them.
//
//   <Parameter name="Maximum iterations" type="int" value="200"/>
//   <Parameter name="Restart" type="int" value="60"/>
//   <Parameter name="Recycled products" type="int" value="0"/>
//   <Parameter name="Largest error factor" type="double" value="2"/>
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::operators {

struct StageSolverSettings {
  int maximumIterations = 200; ///< GMRES iterations of one stage solve before it counts as failed
  int restart = 60;            ///< Krylov vectors kept (Belos "Num Blocks")
  int recycledProducts = 0;    ///< products of J~ a step keeps (JacobianProducts.hpp)
  /// A solve's error, largest coordinate, at most this times its RMS residual target
  /// (StageSolver::boundLargestError; 0: not checked).
  double largestErrorFactor = 2.0;
};

/// Declares the four keys in `stiff`; `unknownsPerNode` (3 in 3D, 2 in 2D) sizes the memory
/// their doc strings state.
void declareStageSolverParameters(Teuchos::ParameterList& stiff, int unknownsPerNode);

/// Settings from a validated "Stiff" sublist.
StageSolverSettings readStageSolverSettings(const Teuchos::ParameterList& stiff);

/// "GMRES (restart 60, at most 200 iterations[, from up to k kept products of the step's
/// Jacobian])", for a run's "Terms built".
std::string describe(const StageSolverSettings& settings);

/// The keys to change when a stage solve does not converge, for the failure message.
std::string settingsHint(const StageSolverSettings& settings);

} // namespace capsula::operators
