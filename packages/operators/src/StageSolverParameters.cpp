#include "capsula/operators/StageSolverParameters.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

#include <sstream>

namespace capsula::operators {

void declareStageSolverParameters(Teuchos::ParameterList& stiff, int unknownsPerNode)
{
  const StageSolverSettings defaults;
  core::declareInt(stiff, "Maximum iterations", defaults.maximumIterations,
                   "GMRES iterations of one stage solve of a stiff method before the solve counts as "
                   "failed: the step is then rejected and retried with a quarter of its size.",
                   1, 100000);
  std::ostringstream restart, recycled;
  restart << "Krylov vectors GMRES keeps before it restarts (Belos 'Num Blocks'); each costs " << unknownsPerNode
          << " numbers per node.";
  recycled << "Products of the Jacobian a step keeps (each costs " << unknownsPerNode
           << " numbers per node, twice): every stage solve of the step starts from the combination of them with "
              "the least residual, so GMRES only reduces what they cannot reach (0: each solve starts from zero; "
              "docs/stiff-integration.md).";
  core::declareInt(stiff, "Restart", defaults.restart, restart.str(), 1, 1000);
  core::declareInt(stiff, "Recycled products", defaults.recycledProducts, recycled.str(), 0, 1000);
  core::declareReal(stiff, "Largest error factor", defaults.largestErrorFactor,
                    "Holds each stage solve's error in the step controller's norm: its largest coordinate at "
                    "most this factor times the solve's RMS residual target ('Time integration/Linear tolerance' "
                    "x 'Time integration/Tolerance'), estimated by a correction solve to a tenth of the residual "
                    "(which the solution then takes); a solve that needs more than four corrections counts as "
                    "failed and the step is retried smaller. 0: the RMS residual alone, which cannot see an error "
                    "concentrated on a few coordinates where the stage matrix is nearly singular "
                    "(docs/stiff-integration.md).",
                    core::atLeast(0.0));
}

StageSolverSettings readStageSolverSettings(const Teuchos::ParameterList& stiff)
{
  StageSolverSettings s;
  s.maximumIterations = stiff.get<int>("Maximum iterations");
  s.restart = stiff.get<int>("Restart");
  s.recycledProducts = stiff.get<int>("Recycled products");
  s.largestErrorFactor = stiff.get<double>("Largest error factor");
  return s;
}

std::string describe(const StageSolverSettings& settings)
{
  std::ostringstream line;
  line << "GMRES (restart " << settings.restart << ", at most " << settings.maximumIterations << " iterations";
  if (settings.recycledProducts > 0) {
    line << ", from up to " << settings.recycledProducts << " kept products of the step's Jacobian";
  }
  if (settings.largestErrorFactor > 0.0) {
    line << ", error checked: largest coordinate <= " << settings.largestErrorFactor << " x the RMS target";
  }
  line << ")";
  return line.str();
}

std::string settingsHint(const StageSolverSettings& settings)
{
  std::ostringstream hint;
  hint << "raise 'Solver/Stiff/Maximum iterations' = " << settings.maximumIterations
       << " or 'Solver/Stiff/Restart' = " << settings.restart;
  if (settings.largestErrorFactor > 0.0) {
    hint << ", or 'Solver/Stiff/Largest error factor' = " << settings.largestErrorFactor;
  }
  return hint.str();
}

} // namespace capsula::operators
