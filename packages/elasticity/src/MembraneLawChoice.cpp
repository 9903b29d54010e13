#include "capsula/elasticity/MembraneLawChoice.hpp"

#include <capsula/core/ParameterDeclaration.hpp>
#include <capsula/core/RegisteredNames.hpp>

#include <vector>

namespace capsula::elasticity {

namespace {

const char* const lawKey = "Membrane law";

std::vector<std::string> namesOf(const std::map<std::string, MembraneLawInfo>& laws)
{
  std::vector<std::string> names;
  for (const auto& entry : laws) {
    names.push_back(entry.first);
  }
  return names;
}

} // namespace

void declareMembraneLawParameters(Teuchos::ParameterList& cell, const std::map<std::string, MembraneLawInfo>& laws,
                                  const std::string& defaultLaw, const std::string& purpose)
{
  const std::vector<std::string> names = namesOf(laws);
  core::requireRegistered(membraneLawKind, defaultLaw, names);
  std::string doc = purpose;
  for (const auto& [name, info] : laws) {
    doc += " " + name + ": " + info.description;
  }
  core::declareChoice(cell, lawKey, defaultLaw, names, doc);
  for (const auto& [name, info] : laws) {
    if (info.validParameters.is_null()) {
      continue;
    }
    const Teuchos::ParameterList& keys = *info.validParameters;
    for (auto it = keys.begin(); it != keys.end(); ++it) {
      // A law's key must not take over a key of the cell or of another law.
      core::require<core::InputError>(!cell.isParameter(keys.name(it)), "The key '", keys.name(it),
                                      "' of the membrane law '", name,
                                      "' is declared already beside 'Membrane law'; give the law's key another name.");
      cell.setEntry(keys.name(it), keys.entry(it));
    }
  }
}

MembraneLawChoice readMembraneLawChoice(const Teuchos::ParameterList& cell,
                                        const std::map<std::string, MembraneLawInfo>& laws, const std::string& path)
{
  MembraneLawChoice choice;
  choice.name = cell.get<std::string>(lawKey);
  try {
    core::requireRegistered(membraneLawKind, choice.name, namesOf(laws));
  } catch (const core::InputError& e) {
    throw core::InputError(core::message("'", path, "/", lawKey, "': ", e.what()));
  }
  const MembraneLawInfo& info = laws.at(choice.name);
  if (!info.validParameters.is_null()) {
    const Teuchos::ParameterList& keys = *info.validParameters;
    for (auto it = keys.begin(); it != keys.end(); ++it) {
      choice.parameters.setEntry(keys.name(it),
                                 cell.isParameter(keys.name(it)) ? cell.getEntry(keys.name(it)) : keys.entry(it));
    }
  }
  return choice;
}

} // namespace capsula::elasticity
