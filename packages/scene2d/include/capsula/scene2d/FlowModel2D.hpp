#pragma once
// What drives the 2D cell: the shear flow (Flow/Capillary number, Flow/Viscosity ratio,
// Flow/Shear rate: k(t) over its mean, operators/ShearRate.hpp), the fluid domain in the x-y
// plane (Wall/Enabled: above the wall y = 0, Blake's 2D Green's function, thesis App. B.1; or
// unbounded), a domain::Domain that every consumer asks, and the Green's function that
// describes it ('Operator/Kernel', operators/KernelChoice.hpp: Auto follows the domain).
// Dimensionless as in the thesis: u_inf = (y, 0), time in 1/k.
#include "capsula/scene2d/InterfaceVelocity2D.hpp"
#include "capsula/scene2d/KernelRegistry2D.hpp"

#include <capsula/domain/Domain.hpp>
#include <capsula/operators/KernelChoice.hpp>
#include <capsula/operators/ShearRate.hpp>

#include <Teuchos_ParameterList.hpp>

namespace capsula::scene2d {

struct FlowSettings2D {
  FlowConditions2D conditions;                         ///< Ca, lambda, u_inf = (y, 0) at the mean shear rate
  operators::ShearRate shearRate;                      ///< k(t) over its mean: u_inf = (k(t) y, 0) at time t
  domain::Domain domain = domain::Domain::aboveWall(); ///< Wall/Enabled: above the wall, or unbounded
  operators::KernelChoice kernel{"Wall", {}};          ///< the registry name (Auto resolved) and settings
};

/// Declares Capillary number, Viscosity ratio and the Shear rate sublist in `flow`.
void declareFlowParameters2D(Teuchos::ParameterList& flow);
/// Declares Enabled in `wall`.
void declareWallParameters2D(Teuchos::ParameterList& wall);

/// Reads the validated "Flow", "Wall" and "Operator" sublists; the kernel is one of
/// `kernels` (an "Operator" list without 'Kernel': Auto). Throws core::InputError for an
/// unknown kernel or one for the other fluid domain (KernelChoice.hpp).
FlowSettings2D readFlowSettings2D(const Teuchos::ParameterList& flow, const Teuchos::ParameterList& wall,
                                  const Teuchos::ParameterList& operatorList = {},
                                  const KernelRegistry2D& kernels = builtInKernels2D());

} // namespace capsula::scene2d
