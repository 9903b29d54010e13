#include "capsula/operators/KernelChoice.hpp"

#include "capsula/operators/RegisteredNames.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <vector>

namespace capsula::operators {

namespace {

const char* const automaticChoice = "Auto";

FluidDomain fluidOf(const domain::Domain& domain)
{
  return domain.hasUpperWall()   ? FluidDomain::Channel
         : domain.hasLowerWall() ? FluidDomain::AboveWall
                                 : FluidDomain::Unbounded;
}

std::string describeKernelDomain(const KernelInfo& info)
{
  const std::string walls = info.domain == FluidDomain::Channel     ? "a channel between two walls"
                            : info.domain == FluidDomain::AboveWall ? "the fluid above the wall y = 0"
                                                                    : "an unbounded fluid";
  return walls + (info.periodic ? ", periodic along x and z" : " without periodic directions");
}

// The keys that describe the deck's domain, with their values ('Wall/Enabled' always, the
// others where they differ from their default 0).
std::string domainKeys(const domain::Domain& domain)
{
  const auto& shape = domain.shape();
  std::string keys = core::message("'Wall/Enabled' = ", shape.lowerWall ? "true" : "false");
  if (shape.channelHeight > 0.0) {
    keys += core::message(", 'Wall/Channel height' = ", shape.channelHeight);
  }
  if (shape.periodX > 0.0) {
    keys += core::message(", 'Domain/Periodic length x' = ", shape.periodX);
  }
  if (shape.periodZ > 0.0) {
    keys += core::message(", 'Domain/Periodic length z' = ", shape.periodZ);
  }
  return keys;
}

std::string automaticKernel(const std::map<std::string, KernelInfo>& kernels, const domain::Domain& domain)
{
  if (!domain.hasUpperWall() && !domain.isPeriodic()) {
    return domain.hasLowerWall() ? "Wall" : "FreeSpace";
  }
  std::string listed;
  for (const auto& [name, info] : kernels) {
    if (servesDomain(info, domain)) {
      return name;
    }
    listed += core::message(listed.empty() ? "" : "; ", name, ": ", describeKernelDomain(info));
  }
  throw core::InputError(core::message("No registered Green's function serves ", domain.describe(), " (",
                                       domainKeys(domain), "). The kernels of this program serve: ", listed,
                                       ". Change the domain's keys, or run a program whose operator libraries "
                                       "register a kernel for this domain ('Operator/Kernel', docs/domains.md)."));
}

} // namespace

bool servesDomain(const KernelInfo& info, const domain::Domain& domain)
{
  // A periodic kernel is periodic along both x and z: a domain periodic in one direction
  // only is served by none of them.
  const bool doublyPeriodic = domain.isPeriodic(domain::flowAxis) && domain.isPeriodic(domain::vorticityAxis);
  return info.domain == fluidOf(domain) && (info.periodic ? doublyPeriodic : !domain.isPeriodic());
}

void declareKernelParameters(Teuchos::ParameterList& operatorList, const std::map<std::string, KernelInfo>& kernels)
{
  std::vector<std::string> choices{automaticChoice};
  std::string doc = "The Green's function of the boundary-integral operators. Auto: without a channel and periodic "
                    "directions, Wall when 'Wall/Enabled' is true and FreeSpace otherwise; else the registered kernel "
                    "that serves the domain (docs/domains.md).";
  for (const auto& [name, info] : kernels) {
    choices.push_back(name);
    doc += " " + name + ": " + info.description;
  }
  doc += " A named kernel must be for the domain the deck describes ('Wall/Enabled', 'Wall/Channel height', "
         "'Domain/Periodic length x', 'z'; docs/extending.md).";
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
                              const std::map<std::string, KernelInfo>& kernels, const domain::Domain& domain)
{
  const std::string requested =
      operatorList.isParameter("Kernel") ? operatorList.get<std::string>("Kernel") : automaticChoice;
  KernelChoice choice;
  choice.name = requested != automaticChoice ? requested : automaticKernel(kernels, domain);
  std::vector<std::string> names;
  for (const auto& entry : kernels) {
    names.push_back(entry.first);
  }
  requireRegistered("Green's function kernel", choice.name, names);
  const KernelInfo& info = kernels.at(choice.name);
  core::require<core::InputError>(servesDomain(info, domain), "'Operator/Kernel' = ", choice.name, " is for ",
                                  describeKernelDomain(info), " but the deck (", domainKeys(domain), ") describes ",
                                  domain.describe(), ": change one of the two, or set 'Operator/Kernel' = Auto.");
  if (!info.validParameters.is_null()) {
    choice.parameters = *info.validParameters;
    if (operatorList.isSublist(choice.name)) {
      choice.parameters.setParameters(operatorList.sublist(choice.name));
    }
  }
  return choice;
}

} // namespace capsula::operators
