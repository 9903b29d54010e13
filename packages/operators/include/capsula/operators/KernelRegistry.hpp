#pragma once
// Deck name -> BoundaryIntegralSolver for that Green's function.
//
// The scene asks the registry for the kernel 'Operator/Kernel' names (KernelChoice.hpp;
// "FreeSpace", "Wall" built in); a new kernel (periodic, channel) is a new library that
// registers a factory, usually solverFactory<Policy>() from KernelBoundaryIntegralSolver.hpp,
// with its fluid domain and its own deck settings. Nothing global: the application owns
// the registry and decides what it holds (docs/extending.md).
#include <capsula/operators/BoundaryIntegralSolver.hpp>
#include <capsula/operators/FarFieldBackEnd.hpp>
#include <capsula/operators/KernelCatalogue.hpp>
#include <capsula/operators/OperatorParameters.hpp>

#include <capsula/domain/Domain.hpp>

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <string>

namespace capsula::operators {

/// Builds the operator of one kernel; `kernelParameters` are its settings ('Operator/<name>',
/// defaults filled in; empty for a kernel without settings) and `domain` the deck's fluid
/// domain (a periodic kernel takes its periods from it; KernelChoice has checked that the
/// kernel serves it).
using SolverFactory = std::function<std::unique_ptr<BoundaryIntegralSolver>(
    const Teuchos::RCP<const Teuchos::Comm<int>>& comm, CellSurfaces surfaces,
    const DiscretisationParameters& discretisation, const SolverParameters& solver,
    const Teuchos::ParameterList& kernelParameters, const domain::Domain& domain)>;

class KernelRegistry : public KernelCatalogue<SolverFactory> {
public:
  /// The far-field back-end ('Operator/Summation') of every solver created, unless the
  /// discretisation passed to create names its own; null (the default): direct sums.
  void setFarField(std::shared_ptr<const FarFieldBackEnd> farField) { farField_ = std::move(farField); }
  const std::shared_ptr<const FarFieldBackEnd>& farField() const { return farField_; }

  /// A solver for the kernel `name` with its settings `kernelParameters`
  /// (KernelChoice::parameters) in the fluid `domain`. Throws core::InputError naming the registered kernels
  /// (and the closest one) if there is none by that name, or naming 'Operator/Summation'
  /// if the far-field back-end does not support that kernel.
  std::unique_ptr<BoundaryIntegralSolver> create(const std::string& name,
                                                 const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                                 CellSurfaces surfaces, const DiscretisationParameters& discretisation,
                                                 const SolverParameters& solver,
                                                 const Teuchos::ParameterList& kernelParameters = {},
                                                 const domain::Domain& domain = domain::Domain::unbounded()) const;

private:
  std::shared_ptr<const FarFieldBackEnd> farField_;
};

/// Registers "FreeSpace" (unbounded fluid, eqs 3.11-3.12) and "Wall" (plane wall y = 0,
/// fluid y > 0, Blake 1971, App. B.2).
void registerBuiltInKernels(KernelRegistry& registry);

/// A registry holding the built-in kernels.
KernelRegistry builtInKernels();

} // namespace capsula::operators
