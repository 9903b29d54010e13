#include "capsula/operators/SummationRegistry.hpp"

#include "capsula/operators/RegisteredNames.hpp"

#include <capsula/core/Error.hpp>
#include <capsula/core/ParameterDeclaration.hpp>

#include <sstream>

namespace capsula::operators {

namespace {

const char* const directSummation = "Direct";

} // namespace

void SummationRegistry::add(const std::string& name, const std::string& description, FarFieldFactory factory,
                            Teuchos::RCP<const Teuchos::ParameterList> validParameters)
{
  core::require<core::InputError>(!name.empty(), "A summation back-end needs a non-empty name to be registered.");
  core::require<core::InputError>(!contains(name), "A summation back-end named '", name, "' is registered already.");
  core::require<core::InputError>(static_cast<bool>(factory), "The summation back-end '", name, "' has no factory.");
  entries_.emplace(name, Entry{description, std::move(factory), std::move(validParameters)});
}

std::vector<std::string> SummationRegistry::names() const
{
  std::vector<std::string> result;
  for (const auto& entry : entries_) {
    result.push_back(entry.first);
  }
  return result;
}

const SummationRegistry::Entry& SummationRegistry::entry(const std::string& name) const
{
  requireRegistered("summation back-end", name, names());
  return entries_.at(name);
}

const std::string& SummationRegistry::description(const std::string& name) const
{
  return entry(name).description;
}

const Teuchos::RCP<const Teuchos::ParameterList>& SummationRegistry::validParameters(const std::string& name) const
{
  return entry(name).validParameters;
}

std::shared_ptr<const FarFieldBackEnd> SummationRegistry::create(const std::string& name,
                                                                 const Teuchos::ParameterList& settings) const
{
  const Entry& chosen = entry(name);
  Teuchos::ParameterList withDefaults;
  if (!chosen.validParameters.is_null()) {
    withDefaults = *chosen.validParameters;
  }
  withDefaults.setParameters(settings);
  return chosen.factory(withDefaults);
}

SummationRegistry builtInSummations()
{
  SummationRegistry registry;
  registry.add(directSummation, "exactly, vectorised.",
               [](const Teuchos::ParameterList&) { return std::shared_ptr<const FarFieldBackEnd>(); });
  return registry;
}

void declareSummationParameters(Teuchos::ParameterList& operatorList, const SummationRegistry& summations)
{
  std::string doc = "How the regular quadrature sums of the single and double layer (every target against every "
                    "quadrature point, O(N M)) are computed; the singular and near-singular corrections stay "
                    "exact either way (docs/fastsum.md).";
  for (const auto& name : summations.names()) {
    doc += " " + name + ": " + summations.description(name);
  }
  doc += " A kernel with a far-field sum of its own (the periodic kernels' spectral Ewald sums) uses it under " +
         std::string(directSummation) + " and refuses the others.";
  core::declareChoice(operatorList, "Summation", directSummation, summations.names(), doc);
  for (const auto& name : summations.names()) {
    const auto& keys = summations.validParameters(name);
    if (keys.is_null()) {
      continue;
    }
    // A back-end's sublist must not take over a key another component declared.
    core::require<core::InputError>(!operatorList.isParameter(name), "The settings of the summation back-end '", name,
                                    "' would replace 'Operator/", name, "'; register it under another name.");
    core::declareSublist(operatorList, name, "The settings of 'Operator/Summation' = " + name + ".")
        .setParameters(*keys);
  }
}

namespace {

// The settings of a back-end other than the chosen one have no effect: a value other than
// its default is refused, as every key a scene does not use (docs/user-guide.md, "Keys
// without effect").
void requireUnusedBackEndsAtDefault(const Teuchos::ParameterList& operatorList, const SummationRegistry& summations,
                                    const std::string& chosen)
{
  for (const auto& name : summations.names()) {
    const auto& defaults = summations.validParameters(name);
    if (name == chosen || defaults.is_null() || !operatorList.isSublist(name)) {
      continue;
    }
    const Teuchos::ParameterList& given = operatorList.sublist(name);
    for (auto it = given.begin(); it != given.end(); ++it) {
      const std::string& key = given.name(it);
      const Teuchos::ParameterEntry& entry = given.entry(it);
      if (!defaults->isParameter(key) || entry.getAny() == defaults->getEntry(key).getAny()) {
        continue;
      }
      std::ostringstream value;
      value << entry.getAny();
      throw core::InputError(core::message("'Operator/", name, "/", key, "' = ", value.str(),
                                           " has no effect with 'Operator/Summation' = ", chosen,
                                           ": set 'Operator/Summation' = ", name, " or remove the key."));
    }
  }
}

} // namespace

std::shared_ptr<const FarFieldBackEnd> readFarFieldBackEnd(const Teuchos::ParameterList& operatorList,
                                                           const SummationRegistry& summations)
{
  const std::string name =
      operatorList.isParameter("Summation") ? operatorList.get<std::string>("Summation") : directSummation;
  requireUnusedBackEndsAtDefault(operatorList, summations, name);
  const Teuchos::ParameterList none;
  return summations.create(name, operatorList.isSublist(name) ? operatorList.sublist(name) : none);
}

} // namespace capsula::operators
