#include "capsula/scene/StiffSolverParameters.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::scene {

void declareStiffSolverParameters(Teuchos::ParameterList& stiff)
{
  const StiffSolverSettings defaults;
  operators::declareStageSolverParameters(stiff, 3);
  core::declareChoice(stiff, "Preconditioner", "Local mobility", {"Local mobility", "None"},
                      "Local mobility: the stage matrix with the single layer replaced by each node's "
                      "own mobility, a sparse matrix factorised per cell (docs/stiff-integration.md); "
                      "None: plain GMRES (iterations grow with the stiffness).");
  core::declareReal(stiff, "Mobility factor", defaults.mobilityFactor,
                    "beta of the local mobility beta / R_i that stands for the single layer in the "
                    "preconditioner (R_i the radius of the disc of node i's share of the area; the "
                    "single layer of a uniform load of total force F on a disc of radius R is 2 F / R "
                    "(normal) to 3 F / R (tangential) at its centre).",
                    core::greaterThan(0.0));
  core::declareInt(stiff, "Quadrature points", defaults.quadraturePoints,
                   "N_Q of the single layer inside the Jacobian (0: 'Discretisation/Quadrature points'). "
                   "The Jacobian needs to be right only on the fast membrane modes, which the "
                   "singular and near-singular corrections carry, so its regular sums can use a "
                   "smaller rule than the right-hand side's: each application costs about "
                   "N_Q / 7 of one with the thesis's 7 points (docs/stiff-integration.md).",
                   0, 19);
}

StiffSolverSettings readStiffSolverSettings(const Teuchos::ParameterList& stiff)
{
  StiffSolverSettings s;
  s.stage = operators::readStageSolverSettings(stiff);
  s.preconditioned = stiff.get<std::string>("Preconditioner") == "Local mobility";
  s.mobilityFactor = stiff.get<double>("Mobility factor");
  s.quadraturePoints = stiff.get<int>("Quadrature points");
  return s;
}

} // namespace capsula::scene
