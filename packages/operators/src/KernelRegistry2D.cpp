#include "capsula/operators/KernelRegistry2D.hpp"

namespace capsula::operators {

namespace {

SolverFactory2D builtInFactory2D(bool wall)
{
  return [wall](const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                const ContourDiscretisation2D& discretisation, const SolverParameters& solver,
                const Teuchos::ParameterList& /*kernelParameters*/) {
    return makeInterfaceVelocity2D(wall, comm, numNodes, discretisation, solver);
  };
}

} // namespace

void registerBuiltInKernels2D(KernelRegistry2D& registry)
{
  registry.add("FreeSpace", KernelInfo{"Unbounded fluid (thesis eqs A.6-A.9).", FluidDomain::Unbounded, {}},
               builtInFactory2D(false));
  registry.add("Wall", KernelInfo{"Plane wall y = 0, fluid y > 0 (thesis App. B.1).", FluidDomain::AboveWall, {}},
               builtInFactory2D(true));
}

KernelRegistry2D builtInKernels2D()
{
  KernelRegistry2D registry;
  registerBuiltInKernels2D(registry);
  return registry;
}

} // namespace capsula::operators
