#include "capsula/run/OperatorLibraries.hpp"

#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/fastsum/TreecodeRegistration.hpp>
#include <capsula/operators/KernelChoice.hpp>
#include <capsula/periodic/PeriodicKernelLibrary.hpp>

namespace capsula::run {

OperatorLibraries standardOperatorLibraries()
{
  OperatorLibraries libraries{operators::builtInKernels(), operators::builtInSummations()};
  periodic::registerPeriodicKernels(libraries.kernels);
  fastsum::registerTreecodeSummation(libraries.summations);
  return libraries;
}

void declareOperatorLibraryParameters(Teuchos::ParameterList& valid, const OperatorLibraries& libraries)
{
  Teuchos::ParameterList& operatorList =
      core::declareSublist(valid, "Operator",
                           "The Green's function and the far-field sums of the boundary-integral operators "
                           "(docs/extending.md, docs/fastsum.md).");
  operators::declareKernelParameters(operatorList, libraries.kernels.infos());
  operators::declareSummationParameters(operatorList, libraries.summations);
}

operators::KernelRegistry kernelsForDeck(const OperatorLibraries& libraries, const Teuchos::ParameterList& deck)
{
  operators::KernelRegistry kernels = libraries.kernels;
  const Teuchos::ParameterList noOperatorList;
  kernels.setFarField(operators::readFarFieldBackEnd(
      deck.isSublist("Operator") ? deck.sublist("Operator") : noOperatorList, libraries.summations));
  return kernels;
}

} // namespace capsula::run
