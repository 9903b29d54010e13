#include "capsula/scene2d/FlowModel2D.hpp"

#include <capsula/core/ParameterDeclaration.hpp>

namespace capsula::scene2d {

void declareFlowParameters2D(Teuchos::ParameterList& flow)
{
  namespace core = capsula::core;
  core::declareReal(flow, "Capillary number", 0.25,
                    "Ca = mu k L / E (thesis eq A.13): shear rate over membrane stiffness. The thesis "
                    "studied 0.01 to 0.25.",
                    core::greaterThan(0.0));
  core::declareReal(flow, "Viscosity ratio", 1.0,
                    "lambda = inside / outside viscosity. 1 gives the velocity explicitly; otherwise "
                    "a Krylov method solves for it ('Solver/Method'). The thesis studied 1 to 10; time is "
                    "reported as k t / lambda.",
                    core::greaterThan(0.0));
  operators::declareShearRateParameters(core::declareSublist(
      flow, "Shear rate", "The shear rate k(t) over its mean: steady, pulsatile or a tabulated waveform."));
}

void declareWallParameters2D(Teuchos::ParameterList& wall)
{
  capsula::core::declareBool(wall, "Enabled", true,
                             "true: the plane wall y = 0 (no slip) bounds the fluid (thesis App. B.1); "
                             "false: unbounded shear flow.");
}

FlowSettings2D readFlowSettings2D(const Teuchos::ParameterList& flow, const Teuchos::ParameterList& wall,
                                  const Teuchos::ParameterList& operatorList, const KernelRegistry2D& kernels)
{
  FlowSettings2D s;
  s.conditions.capillaryNumber = flow.get<double>("Capillary number");
  s.conditions.viscosityRatio = flow.get<double>("Viscosity ratio");
  s.conditions.background = LinearFlow2D::simpleShear(1.0);
  if (flow.isSublist("Shear rate")) {
    s.shearRate = operators::readShearRate(flow.sublist("Shear rate"), "Flow/Shear rate");
  }
  s.domain = wall.get<bool>("Enabled") ? domain::Domain::aboveWall() : domain::Domain::unbounded();
  s.kernel = operators::readKernelChoice(operatorList, kernels.infos(), s.domain);
  return s;
}

} // namespace capsula::scene2d
