#include "capsula/scene2d/KernelRegistry2D.hpp"

namespace capsula::scene2d {

namespace {

SolverFactory2D builtInFactory2D(bool wall)
{
  return [wall](const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                const ContourDiscretisation2D& discretisation, const operators::SolverParameters& solver,
                const Teuchos::ParameterList& /*kernelParameters*/) {
    return makeInterfaceVelocity2D(wall, comm, numNodes, discretisation, solver);
  };
}

} // namespace

void registerBuiltInKernels2D(KernelRegistry2D& registry)
{
  registry.add("FreeSpace",
               operators::KernelInfo{"Unbounded fluid (thesis eqs A.6-A.9).", operators::FluidDomain::Unbounded, {}},
               builtInFactory2D(false));
  registry.add(
      "Wall",
      operators::KernelInfo{"Plane wall y = 0, fluid y > 0 (thesis App. B.1).", operators::FluidDomain::AboveWall, {}},
      builtInFactory2D(true));
}

KernelRegistry2D builtInKernels2D()
{
  KernelRegistry2D registry;
  registerBuiltInKernels2D(registry);
  return registry;
}

} // namespace capsula::scene2d
