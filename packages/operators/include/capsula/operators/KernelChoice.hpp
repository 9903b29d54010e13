#pragma once
// The deck's choice of the Green's function, in the sublist "Operator": 'Kernel' (Auto or
// a registered name) and, for a kernel with settings of its own, the sublist
// 'Operator/<name>'. The same for 2D and 3D: only the registry's KernelInfo is needed.
//
// Auto keeps every deck written before kernels could be named working: it is Wall with
// 'Wall/Enabled' = true and FreeSpace otherwise. A named kernel must be for the fluid the
// deck describes (KernelInfo::domain), so the wall cannot be half switched on.
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

/// The kernel `operatorList` selects for a fluid with (`wall`) or without the wall y = 0.
/// A list without 'Kernel' means Auto. Throws core::InputError naming the registered
/// kernels for an unknown name, and naming 'Operator/Kernel' and 'Wall/Enabled' when the
/// kernel is for the other fluid domain.
KernelChoice readKernelChoice(const Teuchos::ParameterList& operatorList,
                              const std::map<std::string, KernelInfo>& kernels, bool wall);

} // namespace capsula::operators
