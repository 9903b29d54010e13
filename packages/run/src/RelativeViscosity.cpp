#include "capsula/run/RelativeViscosity.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/operators/StreamwiseMoment.hpp>

#include <limits>

namespace capsula::run {

bool hasRelativeViscosity(const domain::Domain& domain)
{
  return domain.hasUpperWall() && domain.isPeriodic(domain::flowAxis) && domain.isPeriodic(domain::vorticityAxis);
}

std::string relativeViscosityDefinition(const domain::FlowProfile& profile)
{
  return profile.kind() == domain::FlowProfileKind::Poiseuille
             ? "flux: undisturbed flux / flux, the pressure gradient held"
             : "wall shear stress: mean shear stress on the two walls / the fluid's alone, the walls' velocities held";
}

double relativeViscosity(const operators::CellSurfaces& surfaces, const operators::LoadDensity& load,
                         const double* nodeVelocities, double capillaryNumber, const domain::Domain& domain,
                         const domain::FlowProfile& profile, double shearRate)
{
  core::require(hasRelativeViscosity(domain), "relativeViscosity: a channel periodic along x and z is needed.");
  if (shearRate == 0.0) { // an instant of a pulsatile or tabulated flow at rest
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double lowerWall = domain.walls().front().height;
  const double height = domain.channelHeight();
  const double lengthX = domain.period(domain::flowAxis), lengthZ = domain.period(domain::vorticityAxis);
  if (profile.kind() == domain::FlowProfileKind::Poiseuille) {
    const double undisturbed = shearRate * profile.fluxPerWidth() * lengthZ;
    const double cells = operators::streamwiseMoment(surfaces, load, nodeVelocities, capillaryNumber,
                                                     operators::crossSectionFluxWeight(lowerWall, height)) /
                         lengthX;
    return undisturbed / (undisturbed + cells);
  }
  const double cells = operators::streamwiseMoment(surfaces, load, nodeVelocities, capillaryNumber,
                                                   operators::meanWallShearRateWeight(lowerWall, height)) /
                       (lengthX * lengthZ);
  return (shearRate + cells) / shearRate;
}

} // namespace capsula::run
