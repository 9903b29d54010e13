#include "capsula/scene2d/StiffSolverParameters2D.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::scene2d {

std::string toString(StiffPreconditioner2D preconditioner)
{
  switch (preconditioner) {
  case StiffPreconditioner2D::PointSingleLayer:
    return "Point single layer";
  case StiffPreconditioner2D::LocalMobility:
    return "Local mobility";
  case StiffPreconditioner2D::None:
    break;
  }
  return "None";
}

void declareStiffSolverParameters2D(Teuchos::ParameterList& stiff)
{
  const StiffSolverSettings2D defaults;
  operators::declareStageSolverParameters(stiff, 2);
  core::declareChoice(stiff, "Preconditioner", toString(defaults.preconditioner),
                      {toString(StiffPreconditioner2D::PointSingleLayer),
                       toString(StiffPreconditioner2D::LocalMobility), toString(StiffPreconditioner2D::None)},
                      "The stage matrix I - shift J~ with its single layer replaced by a dense matrix "
                      "that is cheap to form, LU-factorised once per step. Point single layer: the "
                      "Green's function between the nodes, each carrying its share of the arc length "
                      "(its own share integrated exactly); Local mobility: each node's own mobility "
                      "c beta l_i only; None: plain GMRES, whose iterations grow with the stiffness "
                      "(docs/stiff-integration.md has the iterations and times of each).");
  core::declareReal(stiff, "Mobility factor", defaults.mobilityFactor,
                    "Preconditioner 'Local mobility': beta of the mobility c beta l_i that stands for "
                    "the single layer at node i (l_i its share of the arc length): on a straight "
                    "contour the single layer of a load alternating from node to node, the stiffest "
                    "mode, is l times the load, beta = 1.",
                    core::greaterThan(0.0));
  core::declareInt(stiff, "Gauss-Legendre points", defaults.gaussLegendrePoints,
                   "N_GL of the single layer inside the Jacobian (0: 'Discretisation/Gauss-Legendre "
                   "points'). The Jacobian needs to be right only on the fast membrane modes, which "
                   "the singular and near-singular rules carry, so its regular sums can use fewer "
                   "points than the right-hand side's: 3 take the same steps and GMRES iterations as "
                   "6 on the thesis decks at two thirds of the cost per application.",
                   0, 20);
}

StiffSolverSettings2D readStiffSolverSettings2D(const Teuchos::ParameterList& stiff)
{
  StiffSolverSettings2D s;
  s.stage = operators::readStageSolverSettings(stiff);
  const std::string preconditioner = stiff.get<std::string>("Preconditioner");
  s.preconditioner =
      preconditioner == toString(StiffPreconditioner2D::PointSingleLayer) ? StiffPreconditioner2D::PointSingleLayer
      : preconditioner == toString(StiffPreconditioner2D::LocalMobility)  ? StiffPreconditioner2D::LocalMobility
                                                                          : StiffPreconditioner2D::None;
  s.mobilityFactor = stiff.get<double>("Mobility factor");
  s.gaussLegendrePoints = stiff.get<int>("Gauss-Legendre points");
  return s;
}

} // namespace capsula::scene2d
