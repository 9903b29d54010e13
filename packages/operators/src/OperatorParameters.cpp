#include "capsula/operators/OperatorParameters.hpp"

#include "capsula/operators/KrylovMethod.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/quadrature/TriangleRule.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace capsula::operators {

namespace core = capsula::core;

namespace {

std::string supportedRuleList()
{
  std::ostringstream out;
  const auto counts = quadrature::supportedTriangleRules();
  for (std::size_t i = 0; i < counts.size(); ++i) {
    out << (i ? ", " : "") << counts[i];
  }
  return out.str();
}

} // namespace

void declareDiscretisationParameters(Teuchos::ParameterList& discretisation)
{
  const DiscretisationParameters defaults;
  core::declareInt(discretisation, "Quadrature points", defaults.quadraturePoints,
                   "N_Q, points of the symmetric Gauss rule on each element away from the target "
                   "(thesis eq 3.39; 1, 3, 4, 6, 7, 9, 12, 13, 16 or 19). 7 (degree 5) is the thesis "
                   "choice; the cost of a velocity evaluation is proportional to N_Q.",
                   1, 19);
  core::declareInt(discretisation, "Singular quadrature points", defaults.singularQuadraturePoints,
                   "N_GL, Gauss-Legendre points per direction of the polar coordinates on the "
                   "elements that hold the target node (thesis eqs 3.42-3.43). docs/operators.md "
                   "gives the error of the polar rules against N_GL.",
                   2, 32);
  core::declareReal(discretisation, "Near-singular tolerance", defaults.nearSingularTolerance,
                    "Accuracy, relative to that element's contribution, to which an element close "
                    "to a target it does not hold (a node of another cell, a flow probe, a node's "
                    "wall image) is integrated by adaptive subdivision. The error estimate is "
                    "conservative (docs/operators.md).",
                    core::greaterThan(0.0), core::lessThan(1.0));
  core::declareReal(discretisation, "Near-singular distance", defaults.nearSingularDistance,
                    "Targets closer than this many element sizes to an element's bounding sphere get "
                    "the adaptive subdivision; farther ones use the N_Q-point rule. 0 turns the "
                    "subdivision off (thesis practice).",
                    core::atLeast(0.0));
  core::declareInt(discretisation, "Regular neighbour rings", defaults.regularNeighbourRings,
                   "Rings of elements around the elements holding a node that keep the N_Q-point "
                   "rule however near (the node lies in their tangent plane, where the rule is far "
                   "more accurate than at the same distance off the surface). 0 subdivides them too: "
                   "more accurate and dearer (docs/operators.md).",
                   0, 10);
}

namespace {

// `surfaces`: the 3D list, which also offers the cell-block preconditioner.
void declareSolverKeys(Teuchos::ParameterList& solver, double defaultTolerance, const std::string& toleranceDoc,
                       bool surfaces)
{
  const SolverParameters defaults;
  declareKrylovMethod(solver);
  core::declareReal(solver, "Tolerance", defaultTolerance,
                    "Stopping tolerance on the relative residual ||b - A u|| / ||b|| of the "
                    "viscosity-ratio equation (used only when some cell has lambda != 1)." +
                        toleranceDoc,
                    core::greaterThan(0.0), core::lessThan(1.0));
  core::declareInt(solver, "Restart", defaults.restart,
                   "Krylov vectors a GMRES method keeps before it restarts (Belos 'Num Blocks').", 1, 1000);
  core::declareInt(solver, "Maximum iterations", defaults.maximumIterations,
                   "Iterations before the solve is declared failed (Belos 'Maximum Iterations').", 1, 100000);
  core::declareBool(solver, "Warm start", true,
                    "Start each solve of a run from the combination of the last 6 solutions "
                    "whose right-hand sides best reproduce the new one (least squares; "
                    "operators::WarmStartHistory) instead of from the right-hand side. RKF45's "
                    "stages are combinations of the same slopes, so the start is close and saves "
                    "iterations. The stopping test is relative to ||b||, so its meaning does not change. The "
                    "checkpoint carries the history: a restarted run still repeats the uninterrupted "
                    "one bit for bit.");
  if (surfaces) {
    core::declareChoice(solver, "Preconditioner", kNoPreconditioner, {kNoPreconditioner, kCellBlockPreconditioner},
                        "How the viscosity-ratio equation is preconditioned. \"None\": the method of "
                        "'Solver/Method' on the equation as it is. \"Cell blocks\": each cell's own double "
                        "layer on itself, a dense block per cell at a viscosity ratio other than 1, "
                        "LU-factorised at each time step's first solve and applied on the right of flexible GMRES "
                        "(which then replaces 'Method' and 'Belos'; 'Tolerance' keeps its meaning). It "
                        "cuts the iterations of crowded scenes (docs/operators.md, \"Cell-block "
                        "preconditioner\") for (3 n)^2 floats per cell of n nodes (15 MB at mesh level 2).");
  }
  declareBelosParameters(solver);
}

} // namespace

void declareSolverParameters(Teuchos::ParameterList& solver)
{
  declareSolverKeys(solver, SolverParameters{}.tolerance, "", /*surfaces=*/false);
}

void declareSurfaceSolverParameters(Teuchos::ParameterList& solver)
{
  declareSolverKeys(solver, kSurfaceSolverTolerance,
                    " The node velocities err by about this much times the largest |u|. The default "
                    "keeps the solve's error well below that of the default RKF45 tolerance; with a "
                    "looser 'Time integration/Tolerance' this can follow it (about 1e-3 x it). "
                    "docs/operators.md gives the errors and iteration counts.",
                    /*surfaces=*/true);
}

void declareOperatorParameters(Teuchos::ParameterList& deck)
{
  declareDiscretisationParameters(
      core::declareSublist(deck, "Discretisation", "Quadrature of the boundary integrals (thesis Section 3.6)."));
  declareSurfaceSolverParameters(
      core::declareSublist(deck, "Solver", "The Krylov solve of the viscosity-ratio equation (thesis Section 3.8)."));
}

DiscretisationParameters readDiscretisationParameters(const Teuchos::ParameterList& discretisation)
{
  DiscretisationParameters p;
  p.quadraturePoints = discretisation.get<int>("Quadrature points");
  p.singularQuadraturePoints = discretisation.get<int>("Singular quadrature points");
  p.nearSingularTolerance = discretisation.get<double>("Near-singular tolerance");
  p.nearSingularDistance = discretisation.get<double>("Near-singular distance");
  p.regularNeighbourRings = discretisation.get<int>("Regular neighbour rings");
  validate(p);
  return p;
}

SolverParameters readSolverParameters(const Teuchos::ParameterList& solver)
{
  SolverParameters p;
  if (solver.isParameter("Method")) {
    p.method = solver.get<std::string>("Method");
  }
  if (solver.isSublist("Belos")) {
    p.belos = solver.sublist("Belos");
  }
  p.tolerance = solver.get<double>("Tolerance");
  p.restart = solver.get<int>("Restart");
  p.maximumIterations = solver.get<int>("Maximum iterations");
  p.warmStart = solver.isParameter("Warm start") && solver.get<bool>("Warm start");
  p.cellBlockPreconditioner =
      solver.isParameter("Preconditioner") && solver.get<std::string>("Preconditioner") == kCellBlockPreconditioner;
  validate(p);
  // As Belos takes them (an int where it takes a double converted).
  p.belos = checkedBelosEntries(p.belos, p.method);
  return p;
}

void requireTriangleRule(int points, const std::string& key)
{
  const auto counts = quadrature::supportedTriangleRules();
  core::require<core::InputError>(std::find(counts.begin(), counts.end(), points) != counts.end(), "'", key,
                                  "' = ", points, " has no symmetric triangle rule; use one of ", supportedRuleList(),
                                  ".");
}

void validate(const DiscretisationParameters& p)
{
  requireTriangleRule(p.quadraturePoints, "Discretisation/Quadrature points");
  core::require<core::InputError>(p.singularQuadraturePoints >= 2 && p.singularQuadraturePoints <= 32,
                                  "'Discretisation/Singular quadrature points' = ", p.singularQuadraturePoints,
                                  " must lie in [2, 32].");
  core::require<core::InputError>(p.nearSingularTolerance > 0.0 && p.nearSingularTolerance < 1.0,
                                  "'Discretisation/Near-singular tolerance' = ", p.nearSingularTolerance,
                                  " must lie in (0, 1), e.g. 1e-6.");
  core::require<core::InputError>(std::isfinite(p.nearSingularDistance) && p.nearSingularDistance >= 0.0,
                                  "'Discretisation/Near-singular distance' = ", p.nearSingularDistance,
                                  " must be >= 0 (element sizes; 0 turns the treatment off).");
  core::require<core::InputError>(p.regularNeighbourRings >= 0 && p.regularNeighbourRings <= 10,
                                  "'Discretisation/Regular neighbour rings' = ", p.regularNeighbourRings,
                                  " must lie in [0, 10].");
}

void validate(const SolverParameters& p)
{
  core::require<core::InputError>(p.tolerance > 0.0 && p.tolerance < 1.0, "'Solver/Tolerance' = ", p.tolerance,
                                  " must lie in (0, 1), e.g. 1e-7.");
  core::require<core::InputError>(p.restart >= 1, "'Solver/Restart' = ", p.restart, " must be >= 1, e.g. 50.");
  core::require<core::InputError>(p.maximumIterations >= 1, "'Solver/Maximum iterations' = ", p.maximumIterations,
                                  " must be >= 1.");
  validateKrylovSettings(p);
}

} // namespace capsula::operators
