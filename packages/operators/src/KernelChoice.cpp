#include "capsula/operators/KernelChoice.hpp"

#include "capsula/operators/RegisteredNames.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <vector>

namespace capsula::operators {

namespace {

const char* const automaticChoice = "Auto";

std::string describeDomain(FluidDomain domain)
{
  return domain == FluidDomain::AboveWall ? "the fluid above the wall y = 0" : "an unbounded fluid";
}

} // namespace

void declareKernelParameters(Teuchos::ParameterList& operatorList, const std::map<std::string, KernelInfo>& kernels)
{
  std::vector<std::string> choices{automaticChoice};
  std::string doc = "The Green's function of the boundary-integral operators. Auto: Wall when 'Wall/Enabled' is "
                    "true, FreeSpace otherwise.";
  for (const auto& [name, info] : kernels) {
    choices.push_back(name);
    doc += " " + name + ": " + info.description;
  }
  doc += " A named kernel must be for the fluid 'Wall/Enabled' describes (docs/extending.md).";
  core::declareChoice(operatorList, "Kernel", automaticChoice, choices, doc);
  for (const auto& [name, info] : kernels) {
    if (info.validParameters.is_null()) {
      continue;
    }
    // A kernel's sublist must not take over a key another component declared.
    core::require<core::InputError>(!operatorList.isParameter(name), "The settings of the kernel '", name,
                                    "' would replace 'Operator/", name, "'; register the kernel under another name.");
    core::declareSublist(operatorList, name, "The settings of 'Operator/Kernel' = " + name + ".")
        .setParameters(*info.validParameters);
  }
}

KernelChoice readKernelChoice(const Teuchos::ParameterList& operatorList,
                              const std::map<std::string, KernelInfo>& kernels, bool wall)
{
  const std::string requested =
      operatorList.isParameter("Kernel") ? operatorList.get<std::string>("Kernel") : automaticChoice;
  KernelChoice choice;
  choice.name = requested != automaticChoice ? requested : wall ? "Wall" : "FreeSpace";
  std::vector<std::string> names;
  for (const auto& entry : kernels) {
    names.push_back(entry.first);
  }
  requireRegistered("Green's function kernel", choice.name, names);
  const KernelInfo& info = kernels.at(choice.name);
  const FluidDomain deckDomain = wall ? FluidDomain::AboveWall : FluidDomain::Unbounded;
  core::require<core::InputError>(info.domain == deckDomain, "'Operator/Kernel' = ", choice.name, " is for ",
                                  describeDomain(info.domain), " but 'Wall/Enabled' = ", wall ? "true" : "false",
                                  " describes ", describeDomain(deckDomain),
                                  ": change one of the two, or set 'Operator/Kernel' = Auto.");
  if (!info.validParameters.is_null()) {
    choice.parameters = *info.validParameters;
    if (operatorList.isSublist(choice.name)) {
      choice.parameters.setParameters(operatorList.sublist(choice.name));
    }
  }
  return choice;
}

} // namespace capsula::operators
