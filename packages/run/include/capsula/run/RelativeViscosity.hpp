#pragma once
// The relative (apparent) viscosity of a suspension in a channel periodic along x and z: the
// viscosity a Newtonian fluid would need to carry the same flow, over the suspending fluid's
// (docs/suspensions.md, "Relative viscosity").
//
//   Poiseuille (the pressure gradient fixed): mu_rel = Q_0 / (Q_0 + Q'), Q_0 = k(t) H^2 L_z / 6
//     the undisturbed flux through a cross-section and Q' = M[W_flux] / L_x the cells'
//     (operators/StreamwiseMoment.hpp);
//   Couette (the walls' velocities fixed): mu_rel = (k(t) + S') / k(t), S' = M[W_shear] / (L_x
//     L_z) the cells' share of the mean shear rate du/dy on the two walls, that is the mean
//     wall shear stress over the fluid's alone.
#include <capsula/domain/Domain.hpp>
#include <capsula/domain/FlowProfile.hpp>
#include <capsula/operators/CellSurfaces.hpp>
#include <capsula/operators/LoadDensity.hpp>

#include <string>

namespace capsula::run {

/// True where relativeViscosity is defined: a channel periodic along x and z.
bool hasRelativeViscosity(const domain::Domain& domain);

/// What mu_rel is taken from in `profile`, for summary.json: "flux" (Poiseuille) or "wall
/// shear stress" (Couette).
std::string relativeViscosityDefinition(const domain::FlowProfile& profile);

/// mu_rel of the cells `surfaces` under the load `load` with node velocities
/// `nodeVelocities` (the double layer's density; may be null when every viscosity ratio is
/// 1), at the undisturbed shear rate k(t) = `shearRate` and capillary number Ca; NaN where k(t) = 0
/// (an instant of a pulsatile flow at rest).
double relativeViscosity(const operators::CellSurfaces& surfaces, const operators::LoadDensity& load,
                         const double* nodeVelocities, double capillaryNumber, const domain::Domain& domain,
                         const domain::FlowProfile& profile, double shearRate);

} // namespace capsula::run
