#include "capsula/scene2d/ModelParameters2D.hpp"

#include "capsula/scene2d/CellContour2D.hpp"
#include "capsula/scene2d/ContourDiscretisation2D.hpp"
#include "capsula/scene2d/FlowModel2D.hpp"
#include "capsula/scene2d/StiffSolverParameters2D.hpp"
#include "capsula/scene2d/TetherProcedure2D.hpp"

#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/operators/KernelChoice.hpp>
#include <capsula/operators/OperatorParameters.hpp>

namespace capsula::scene2d {

void declareModelParameters2D(Teuchos::ParameterList& valid, const KernelRegistry2D& kernels,
                              const MembraneLawRegistry2D& laws)
{
  using core::declareSublist;
  declareFlowParameters2D(declareSublist(valid, "Flow", "The shear flow (thesis eq A.13)."));
  declareWallParameters2D(declareSublist(valid, "Wall", "The plane wall y = 0."));
  operators::declareKernelParameters(
      declareSublist(valid, "Operator", "The Green's function of the contour integrals (docs/extending.md)."),
      kernels.infos());
  declareCellParameters2D(declareSublist(valid, "Cell", "The initial cell contour (thesis Fig. 4.1)."), laws);
  declareTetherParameters2D(declareSublist(valid, "Tether", "The tether procedure (thesis Section 4.1)."));
  declareContourDiscretisation2D(
      declareSublist(valid, "Discretisation", "Quadrature of the contour integrals (thesis App. A.6)."));
  auto& solver = declareSublist(valid, "Solver", "The Krylov solve of the viscosity-ratio equation (thesis App. A.7).");
  operators::declareSolverParameters(solver);
  declareStiffSolverParameters2D(declareSublist(
      solver, "Stiff",
      "The linear solves of the stiff time integrators (Time integration/Method ROS34PW2, ROS2, Auto)."));
}

} // namespace capsula::scene2d
