#pragma once
// The deck's choice of the Green's function, in the sublist "Operator": 'Kernel' (Auto or
// a registered name) and, for a kernel with settings of its own, the sublist
// 'Operator/<name>'. The same for 2D and 3D: only the registry's KernelInfo is needed.
//
// Auto keeps every deck written before kernels could be named working: it is Wall with
// 'Wall/Enabled' = true and FreeSpace otherwise, in a domain without a channel or periodic
// direction. A named kernel must be for the domain the deck describes (KernelInfo::domain
// and ::periodic), so a wall or a period cannot be half switched on.
#include <capsula/domain/Domain.hpp>
#include <capsula/operators/KernelCatalogue.hpp>

#include <Teuchos_ParameterList.hpp>

#include <map>
#include <string>

namespace capsula::operators {

/// The kernel a deck selects, with its settings (defaults filled in; empty if it has none).
struct KernelChoice {
  std::string name;
  Teuchos::ParameterList parameters;
};

/// Declares 'Kernel' in `operatorList` (choices Auto and the names of `kernels`, each
/// described in the doc string) and the sublist of each kernel with settings.
void declareKernelParameters(Teuchos::ParameterList& operatorList, const std::map<std::string, KernelInfo>& kernels);

/// The kernel `operatorList` selects for `domain`. A list without 'Kernel' means Auto: Wall
/// or FreeSpace for a domain without a channel or a periodic direction, otherwise the
/// registered kernel that serves the domain. Throws core::InputError naming the registered
/// kernels for an unknown name, naming 'Operator/Kernel' and the domain's keys when the
/// kernel is for another domain, and naming the domain's keys when no kernel serves it.
KernelChoice readKernelChoice(const Teuchos::ParameterList& operatorList,
                              const std::map<std::string, KernelInfo>& kernels, const domain::Domain& domain);

/// Whether a kernel registered with `info` serves `domain` (its walls and periodicity).
bool servesDomain(const KernelInfo& info, const domain::Domain& domain);

} // namespace capsula::operators
