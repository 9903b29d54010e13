#include "capsula/periodic/PeriodicKernelLibrary.hpp"

#include "capsula/periodic/PeriodicOperators.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <string>
#include <memory>
#include <utility>

namespace capsula::periodic {

namespace {

Teuchos::RCP<const Teuchos::ParameterList> periodicKernelParameters(const std::string& name)
{
  auto keys = Teuchos::rcp(new Teuchos::ParameterList(name));
  core::declareReal(*keys, "Tolerance", 1e-6,
                    "Of the spectral Ewald sums of the regular quadrature (the far field), relative to the largest "
                    "velocity: sets the Ewald splitting's cutoffs, grid and Gaussian support (docs/domains.md). "
                    "1e-6 keeps them well below the discretisation error of the N_Q-point rule.",
                    core::greaterThan(0.0), core::atMost(1e-2));
  return keys;
}

// The periods of the deck's domain; both must be set (the Ewald sums are doubly periodic).
PeriodicBox requireDoublyPeriodic(const domain::Domain& domain, const std::string& kernel)
{
  const double lx = domain.period(domain::flowAxis);
  const double lz = domain.period(domain::vorticityAxis);
  core::require<core::InputError>(lx > 0.0 && lz > 0.0, "'Operator/Kernel' = ", kernel,
                                  " is periodic in x and z, but the deck sets 'Domain/Periodic length x' = ", lx,
                                  " and 'Domain/Periodic length z' = ", lz,
                                  ": set both periods (> 0); a domain periodic in one direction has no kernel.");
  return PeriodicBox{lx, lz};
}

template <class Kernel>
Kernel periodicKernel(const domain::Domain& domain, const Teuchos::ParameterList& settings, const std::string& name)
{
  Kernel kernel;
  kernel.box = requireDoublyPeriodic(domain, name);
  kernel.tolerance = settings.isParameter("Tolerance") ? settings.get<double>("Tolerance") : 1e-6;
  return kernel;
}

} // namespace

void registerPeriodicKernels(operators::KernelRegistry& registry)
{
  using operators::CellSurfaces;
  using operators::DiscretisationParameters;
  using operators::SolverParameters;
  using Comm = Teuchos::RCP<const Teuchos::Comm<int>>;
  registry.add(
      "Periodic",
      operators::KernelInfo{"Fluid periodic in x and z, unbounded in y: the 2P Stokeslet summed by the "
                            "spectral Ewald method (docs/domains.md).",
                            operators::FluidDomain::Unbounded, periodicKernelParameters("Periodic"), true},
      [](const Comm& comm, CellSurfaces surfaces, const DiscretisationParameters& discretisation,
         const SolverParameters& solver, const Teuchos::ParameterList& settings, const domain::Domain& domain) {
        auto kernel = periodicKernel<PeriodicFreeSpaceKernel>(domain, settings, "Periodic");
        return std::unique_ptr<operators::BoundaryIntegralSolver>(
            new operators::KernelBoundaryIntegralSolver<PeriodicFreeSpaceKernel>(comm, std::move(surfaces),
                                                                                 discretisation, solver, kernel));
      });
  registry.add(
      "PeriodicWall",
      operators::KernelInfo{"Fluid above the wall y = 0, periodic in x and z: Blake's Stokeslet summed by "
                            "the spectral Ewald method, its stresslet too (any viscosity ratio; docs/domains.md).",
                            operators::FluidDomain::AboveWall, periodicKernelParameters("PeriodicWall"), true},
      [](const Comm& comm, CellSurfaces surfaces, const DiscretisationParameters& discretisation,
         const SolverParameters& solver, const Teuchos::ParameterList& settings, const domain::Domain& domain) {
        auto kernel = periodicKernel<PeriodicWallKernel>(domain, settings, "PeriodicWall");
        return std::unique_ptr<operators::BoundaryIntegralSolver>(
            new operators::KernelBoundaryIntegralSolver<PeriodicWallKernel>(comm, std::move(surfaces), discretisation,
                                                                            solver, kernel));
      });
  registry.add(
      "PeriodicChannel",
      operators::KernelInfo{"Fluid between the walls y = 0 and y = H ('Wall/Channel height'), periodic in x "
                            "and z: the channel's Stokeslet summed by the spectral Ewald method, plane "
                            "Couette or Poiseuille flow, any viscosity ratio (docs/domains.md).",
                            operators::FluidDomain::Channel, periodicKernelParameters("PeriodicChannel"), true},
      [](const Comm& comm, CellSurfaces surfaces, const DiscretisationParameters& discretisation,
         const SolverParameters& solver, const Teuchos::ParameterList& settings, const domain::Domain& domain) {
        auto kernel = periodicKernel<PeriodicChannelKernel>(domain, settings, "PeriodicChannel");
        core::require<core::InputError>(domain.hasUpperWall(),
                                        "'Operator/Kernel' = PeriodicChannel needs a channel: set 'Wall/"
                                        "Channel height' > 0.");
        kernel.local.height = domain.channelHeight();
        return std::unique_ptr<operators::BoundaryIntegralSolver>(
            new operators::KernelBoundaryIntegralSolver<PeriodicChannelKernel>(comm, std::move(surfaces),
                                                                               discretisation, solver, kernel));
      });
}

} // namespace capsula::periodic
