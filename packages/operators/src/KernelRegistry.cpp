#include "capsula/operators/KernelRegistry.hpp"

#include "capsula/operators/BuiltInKernels.hpp"

namespace capsula::operators {

std::unique_ptr<BoundaryIntegralSolver>
KernelRegistry::create(const std::string& name, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                       CellSurfaces surfaces, const DiscretisationParameters& discretisation,
                       const SolverParameters& solver, const Teuchos::ParameterList& kernelParameters,
                       const domain::Domain& domain) const
{
  if (farField_ && !discretisation.farField) {
    DiscretisationParameters withFarField = discretisation;
    withFarField.farField = farField_;
    return factory(name)(comm, std::move(surfaces), withFarField, solver, kernelParameters, domain);
  }
  return factory(name)(comm, std::move(surfaces), discretisation, solver, kernelParameters, domain);
}

void registerBuiltInKernels(KernelRegistry& registry)
{
  registry.add("FreeSpace", KernelInfo{"Unbounded fluid (thesis eqs 3.11-3.12).", FluidDomain::Unbounded, {}},
               solverFactory<FreeSpace3DKernel>());
  registry.add("Wall",
               KernelInfo{"Plane wall y = 0, fluid y > 0 (Blake 1971; thesis App. B.2).", FluidDomain::AboveWall, {}},
               solverFactory<Wall3DKernel>());
}

KernelRegistry builtInKernels()
{
  KernelRegistry registry;
  registerBuiltInKernels(registry);
  return registry;
}

} // namespace capsula::operators
