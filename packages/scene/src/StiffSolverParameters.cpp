#include "capsula/scene/StiffSolverParameters.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::scene {

void declareStiffSolverParameters(Teuchos::ParameterList& stiff)
{
  const StiffSolverSettings defaults;
  core::declareInt(stiff, "Maximum iterations", defaults.maximumIterations,
                   "GMRES iterations of one stage solve of a stiff method before the solve counts as "
                   "failed: the step is then rejected and retried with a quarter of its size.",
                   1, 100000);
  core::declareInt(stiff, "Restart", defaults.restart,
                   "Krylov vectors GMRES keeps before it restarts (Belos 'Num Blocks'); each costs "
                   "3 numbers per node.",
                   1, 1000);
  core::declareInt(stiff, "Recycled products", defaults.recycledProducts,
                   "Products of the Jacobian a step keeps (each costs 3 numbers per node, twice): "
                   "every stage solve of the step starts from the combination of them with the "
                   "least residual, so GMRES only reduces what they cannot reach (0: each solve "
                   "starts from zero; docs/stiff-integration.md).",
                   0, 1000);
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
  s.maximumIterations = stiff.get<int>("Maximum iterations");
  s.restart = stiff.get<int>("Restart");
  s.recycledProducts = stiff.get<int>("Recycled products");
  s.preconditioned = stiff.get<std::string>("Preconditioner") == "Local mobility";
  s.mobilityFactor = stiff.get<double>("Mobility factor");
  s.quadraturePoints = stiff.get<int>("Quadrature points");
  return s;
}

} // namespace capsula::scene
