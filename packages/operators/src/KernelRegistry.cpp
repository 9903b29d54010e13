#include "capsula/operators/KernelRegistry.hpp"

#include "capsula/operators/BuiltInKernels.hpp"

#include <capsula/core/DeckValidators.hpp>
#include <capsula/core/Error.hpp>

#include <sstream>

namespace capsula::operators {

namespace core = capsula::core;

void KernelRegistry::add(const std::string& name, const std::string& description, SolverFactory factory)
{
  core::require<core::InputError>(!name.empty(), "A kernel needs a non-empty name to be registered.");
  core::require<core::InputError>(!contains(name), "A kernel named '", name, "' is registered already.");
  core::require<core::InputError>(static_cast<bool>(factory), "The kernel '", name, "' has no factory.");
  entries_.emplace(name, Entry{description, std::move(factory)});
}

std::vector<std::string> KernelRegistry::names() const
{
  std::vector<std::string> result;
  for (const auto& [name, entry] : entries_) {
    result.push_back(name);
  }
  return result;
}

const KernelRegistry::Entry& KernelRegistry::entry(const std::string& name) const
{
  const auto it = entries_.find(name);
  if (it == entries_.end()) {
    std::ostringstream known;
    for (const auto& registered : names()) {
      known << (known.tellp() > 0 ? ", " : "") << registered;
    }
    const auto closest = core::closestMatch(name, names());
    throw core::InputError(core::message("There is no Green's function kernel named '", name, "'; registered: ",
                                         known.str(), ".", closest ? " Did you mean '" + *closest + "'?" : ""));
  }
  return it->second;
}

const std::string& KernelRegistry::description(const std::string& name) const
{
  return entry(name).description;
}

std::unique_ptr<BoundaryIntegralSolver> KernelRegistry::create(const std::string& name,
                                                               const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                                               CellSurfaces surfaces,
                                                               const DiscretisationParameters& discretisation,
                                                               const SolverParameters& solver) const
{
  if (farField_ && !discretisation.farField) {
    DiscretisationParameters withFarField = discretisation;
    withFarField.farField = farField_;
    return entry(name).factory(comm, std::move(surfaces), withFarField, solver);
  }
  return entry(name).factory(comm, std::move(surfaces), discretisation, solver);
}

void registerBuiltInKernels(KernelRegistry& registry)
{
  registry.add("FreeSpace", "Unbounded fluid (thesis eqs 3.11-3.12).", solverFactory<FreeSpace3DKernel>());
  registry.add("Wall", "Plane wall y = 0, fluid y > 0 (Blake 1971; thesis App. B.2).", solverFactory<Wall3DKernel>());
}

KernelRegistry builtInKernels()
{
  KernelRegistry registry;
  registerBuiltInKernels(registry);
  return registry;
}

} // namespace capsula::operators
