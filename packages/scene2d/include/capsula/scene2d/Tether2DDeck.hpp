#pragma once
// The deck of the 2D tethered-cell study (apps/tether2d), assembled from the declarations
// of the components that read each sublist:
//   Flow, Wall, Cell, Tether, Discretisation, Solver   scene2d/ModelParameters2D.hpp
//   Time integration           timeint/TimeIntegrationParameters.hpp; here End time is the
//                              duration of the tethered stage in tau = k (t - t0) / lambda,
//                              step sizes are in k t
//   Output                     TetherRun2D.hpp
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace capsula::scene2d {

Teuchos::RCP<const Teuchos::ParameterList> validTether2DParameters();

} // namespace capsula::scene2d
