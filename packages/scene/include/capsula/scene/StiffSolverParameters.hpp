#pragma once
// The deck's "Solver/Stiff" sublist: the linear solves of the stiff time integrators
// (Time integration/Method ROS34PW2, ROS2, Auto), read by VelocityJacobian.
//
//   <ParameterList name="Stiff">
//     <Parameter name="Maximum iterations" type="int" value="200"/>
//     <Parameter name="Restart" type="int" value="60"/>
//     <Parameter name="Recycled products" type="int" value="0"/>
//     <Parameter name="Preconditioner" type="string" value="Local mobility"/>
//     <Parameter name="Mobility factor" type="double" value="2.5"/>
//     <Parameter name="Quadrature points" type="int" value="3"/>
//   </ParameterList>
#include <capsula/operators/StageSolverParameters.hpp>

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace capsula::scene {

struct StiffSolverSettings {
  operators::StageSolverSettings stage; ///< iteration cap, restart, kept products of J~
  bool preconditioned = true;           ///< "Local mobility" (true) or "None"
  double mobilityFactor = 2.5;          ///< beta of the local mobility beta / R_i (LocalMobilityPreconditioner.hpp)
  int quadraturePoints = 3;             ///< N_Q of J~'s single layer (0: Discretisation/Quadrature points)
};

/// Declares the keys of the "Stiff" sublist in `stiff`.
void declareStiffSolverParameters(Teuchos::ParameterList& stiff);

/// Settings from a validated "Stiff" sublist.
StiffSolverSettings readStiffSolverSettings(const Teuchos::ParameterList& stiff);

} // namespace capsula::scene
