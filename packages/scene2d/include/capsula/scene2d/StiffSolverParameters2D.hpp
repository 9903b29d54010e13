#pragma once
// The tether2d deck's "Solver/Stiff" sublist: the linear solves of the stiff time
// integrators (Time integration/Method ROS34PW2, ROS2, Auto), read by VelocityJacobian2D.
//
//   <ParameterList name="Stiff">
//     <Parameter name="Maximum iterations" type="int" value="200"/>
//     <Parameter name="Restart" type="int" value="60"/>
//     <Parameter name="Recycled products" type="int" value="0"/>
//     <Parameter name="Preconditioner" type="string" value="Point single layer"/>
//     <Parameter name="Mobility factor" type="double" value="1"/>
//     <Parameter name="Gauss-Legendre points" type="int" value="3"/>
//   </ParameterList>
#include <capsula/operators/StageSolverParameters.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::scene2d {

/// What stands for the single layer in the dense stage preconditioner (VelocityJacobian2D.hpp).
enum class StiffPreconditioner2D { PointSingleLayer, LocalMobility, None };

struct StiffSolverSettings2D {
  operators::StageSolverSettings stage; ///< iteration cap, restart, kept products of J~
  StiffPreconditioner2D preconditioner = StiffPreconditioner2D::PointSingleLayer;
  double mobilityFactor = 1.0; ///< beta of the local mobility c beta l_i (VelocityJacobian2D.hpp)
  int gaussLegendrePoints = 3; ///< N_GL of J~'s single layer (0: Discretisation/Gauss-Legendre points)
};

/// Declares the keys of the "Stiff" sublist in `stiff`.
void declareStiffSolverParameters2D(Teuchos::ParameterList& stiff);

/// Settings from a validated "Stiff" sublist.
StiffSolverSettings2D readStiffSolverSettings2D(const Teuchos::ParameterList& stiff);

/// The deck spelling of a preconditioner ("Point single layer", "Local mobility", "None").
std::string toString(StiffPreconditioner2D preconditioner);

} // namespace capsula::scene2d
