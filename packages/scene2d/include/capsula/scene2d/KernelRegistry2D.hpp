#pragma once
// Deck name -> InterfaceVelocity2D for that Green's function, the 2D counterpart of
// KernelRegistry: tether2d asks it for the kernel 'Operator/Kernel' names (KernelChoice.hpp;
// "FreeSpace" and "Wall" built in). The application owns it (docs/extending.md).
#include "capsula/scene2d/ContourDiscretisation2D.hpp"
#include "capsula/scene2d/InterfaceVelocity2D.hpp"

#include <capsula/operators/KernelCatalogue.hpp>
#include <capsula/operators/OperatorParameters.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <functional>
#include <memory>
#include <string>

namespace capsula::scene2d {

/// Builds the evaluator of one kernel for contours of `numNodes` nodes; `kernelParameters`
/// are its settings ('Operator/<name>', defaults filled in; empty without settings).
using SolverFactory2D = std::function<std::unique_ptr<InterfaceVelocity2D>(
    const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes, const ContourDiscretisation2D& discretisation,
    const operators::SolverParameters& solver, const Teuchos::ParameterList& kernelParameters)>;

class KernelRegistry2D : public operators::KernelCatalogue<SolverFactory2D> {
public:
  /// The evaluator of the kernel `name`. Throws core::InputError naming the registered
  /// kernels if there is none by that name.
  std::unique_ptr<InterfaceVelocity2D> create(const std::string& name,
                                              const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int numNodes,
                                              const ContourDiscretisation2D& discretisation,
                                              const operators::SolverParameters& solver,
                                              const Teuchos::ParameterList& kernelParameters = {}) const
  {
    return factory(name)(comm, numNodes, discretisation, solver, kernelParameters);
  }
};

/// Registers "FreeSpace" (unbounded fluid) and "Wall" (plane wall y = 0, Blake's 2D image
/// system, thesis App. B.1): makeInterfaceVelocity2D's two evaluators.
void registerBuiltInKernels2D(KernelRegistry2D& registry);

/// A registry holding the built-in 2D kernels.
KernelRegistry2D builtInKernels2D();

} // namespace capsula::scene2d
