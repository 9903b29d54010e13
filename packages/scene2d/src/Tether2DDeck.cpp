#include "capsula/scene2d/Tether2DDeck.hpp"

#include "capsula/scene2d/ModelParameters2D.hpp"
#include "capsula/scene2d/TetherOutputs2D.hpp"

#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/timeint/TimeIntegrationParameters.hpp>

namespace capsula::scene2d {

Teuchos::RCP<const Teuchos::ParameterList> validTether2DParameters()
{
  using core::declareSublist;
  auto valid = Teuchos::rcp(new Teuchos::ParameterList("tether2d"));
  declareModelParameters2D(*valid);
  auto& time = declareSublist(*valid, "Time integration",
                              "Time stepping (thesis App. A.8). End time: duration of the tethered "
                              "stage in tau = k (t - t0) / lambda; step sizes in k t.");
  timeint::declareTimeIntegrationParameters(time);
  declareOutputParameters2D(declareSublist(*valid, "Output", "What the run writes and how often."));
  return valid;
}

} // namespace capsula::scene2d
