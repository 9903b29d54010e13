#pragma once
// Helpers of the periodic kernels' tests: solvers for a box, and the quadrature of a solver.
#include "OperatorTesting.hpp"

#include <capsula/domain/Domain.hpp>
#include <capsula/operators/BuiltInKernels.hpp>
#include <capsula/periodic/PeriodicKernelLibrary.hpp>
#include <capsula/periodic/PeriodicOperators.hpp>

#include <memory>
#include <string>
#include <vector>

namespace capsula::periodic::testing {

inline operators::KernelRegistry periodicRegistry()
{
  operators::KernelRegistry registry = operators::builtInKernels();
  registerPeriodicKernels(registry);
  return registry;
}

/// The domain periodic in x and z with periods lx, lz, with or without the lower wall.
inline domain::Domain box(double lx, double lz, bool wall)
{
  return domain::Domain(domain::DomainShape{wall, 0.0, lx, lz});
}

/// The channel 0 < y < H periodic in x and z with periods lx, lz.
inline domain::Domain channel(double lx, double lz, double height)
{
  return domain::Domain(domain::DomainShape{true, height, lx, lz});
}

/// A solver of `kernel` ("Periodic", "PeriodicWall", "PeriodicChannel", "FreeSpace", "Wall") for `cells` in
/// `domain`, its Ewald sums to `tolerance`.
inline std::unique_ptr<operators::BoundaryIntegralSolver>
makeSolver(const std::string& kernel, std::vector<mesh::SurfaceMesh> cells, std::vector<double> lambdas,
           const domain::Domain& domain, double tolerance = 1e-10,
           const Teuchos::RCP<const Teuchos::Comm<int>>& comm = operators::testing::serialComm())
{
  const operators::KernelRegistry registry = periodicRegistry();
  Teuchos::ParameterList settings;
  if (kernel == "Periodic" || kernel == "PeriodicWall" || kernel == "PeriodicChannel") {
    settings.set("Tolerance", tolerance);
  }
  operators::SolverParameters solver;
  solver.tolerance = 1e-12;
  return registry.create(kernel, comm, operators::CellSurfaces(std::move(cells), std::move(lambdas)), {}, solver,
                         settings, domain);
}

/// The quadrature of a periodic solver's layer potentials.
template <class Kernel>
const operators::SurfaceQuadrature& quadratureOf(operators::BoundaryIntegralSolver& solver)
{
  auto& typed = dynamic_cast<operators::KernelBoundaryIntegralSolver<Kernel>&>(solver);
  return typed.layerPotentials().quadrature();
}

} // namespace capsula::periodic::testing
