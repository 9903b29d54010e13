#pragma once
// Deck name -> BoundaryIntegralSolver for that Green's function.
//
// The scene asks the registry for the kernel the deck names ("FreeSpace", "Wall"); a new
// kernel (periodic, channel) is a new library that registers a factory, usually
// solverFactory<Policy>() from KernelBoundaryIntegralSolver.hpp. Nothing global: the
// application owns the registry and decides what it holds (docs/extending.md).
#include <capsula/operators/BoundaryIntegralSolver.hpp>
#include <capsula/operators/FarFieldBackEnd.hpp>
#include <capsula/operators/OperatorParameters.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace capsula::operators {

using SolverFactory = std::function<std::unique_ptr<BoundaryIntegralSolver>(
    const Teuchos::RCP<const Teuchos::Comm<int>>& comm, CellSurfaces surfaces,
    const DiscretisationParameters& discretisation, const SolverParameters& solver)>;

class KernelRegistry {
public:
  /// Registers `factory` under `name` with a one-line description for the deck
  /// reference. Throws core::InputError if the name is taken or empty.
  void add(const std::string& name, const std::string& description, SolverFactory factory);

  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  /// Registered names, sorted (the choices of the deck key that selects the kernel).
  std::vector<std::string> names() const;
  const std::string& description(const std::string& name) const;

  /// The far-field back-end ('Operator/Summation') of every solver created, unless the
  /// discretisation passed to create names its own; null (the default): direct sums.
  void setFarField(std::shared_ptr<const FarFieldBackEnd> farField) { farField_ = std::move(farField); }
  const std::shared_ptr<const FarFieldBackEnd>& farField() const { return farField_; }

  /// A solver for the kernel `name`. Throws core::InputError naming the registered
  /// kernels (and the closest one) if there is none by that name, or naming
  /// 'Operator/Summation' if the far-field back-end does not support that kernel.
  std::unique_ptr<BoundaryIntegralSolver> create(const std::string& name,
                                                 const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                                 CellSurfaces surfaces, const DiscretisationParameters& discretisation,
                                                 const SolverParameters& solver) const;

private:
  struct Entry {
    std::string description;
    SolverFactory factory;
  };
  const Entry& entry(const std::string& name) const;
  std::map<std::string, Entry> entries_;
  std::shared_ptr<const FarFieldBackEnd> farField_;
};

/// Registers "FreeSpace" (unbounded fluid, eqs 3.11-3.12) and "Wall" (plane wall y = 0,
/// fluid y > 0, Blake 1971, App. B.2).
void registerBuiltInKernels(KernelRegistry& registry);

/// A registry holding the built-in kernels.
KernelRegistry builtInKernels();

} // namespace capsula::operators
