// The registry of time-integration methods: names, the keys each method owns, and the
// method a settings object names (MethodRegistry.hpp).
#include "capsula/timeint/MethodRegistry.hpp"

#include "capsula/core/DeckValidators.hpp"
#include "capsula/core/Error.hpp"

#include <sstream>
#include <utility>

namespace capsula::timeint {

namespace {

constexpr const char* methodKey = "Time integration/Method";

std::string joined(const std::vector<std::string>& words, const std::string& separator)
{
  std::string text;
  for (const auto& word : words) {
    text += (text.empty() ? "" : separator) + word;
  }
  return text;
}

// A key's value as a deck writes it (true/false for a flag).
std::string deckValue(const Teuchos::ParameterEntry& entry)
{
  if (entry.isType<bool>()) {
    return entry.getValue<bool>(nullptr) ? "true" : "false";
  }
  std::ostringstream text;
  text << entry.getAny(false);
  return text.str();
}

bool sameType(const Teuchos::ParameterEntry& a, const Teuchos::ParameterEntry& b)
{
  return a.getAny(false).type() == b.getAny(false).type();
}

} // namespace

void MethodRegistry::add(const std::string& name, MethodInfo info)
{
  core::require(!has(name), "internal: the time-integration method '", name, "' is registered twice");
  core::require(static_cast<bool>(info.factory), "internal: the time-integration method '", name, "' has no factory");
  if (info.keys) {
    for (auto it = info.keys->begin(); it != info.keys->end(); ++it) {
      const std::string& key = info.keys->name(it);
      const Teuchos::ParameterEntry& entry = info.keys->entry(it);
      for (const auto& other : names_) {
        const auto& keys = methods_.at(other).keys;
        if (keys && keys->isParameter(key)) {
          const Teuchos::ParameterEntry& earlier = keys->getEntry(key);
          core::require(sameType(entry, earlier) && entry.getAny(false) == earlier.getAny(false),
                        "internal: the time-integration methods '", other, "' and '", name,
                        "' declare 'Time integration/", key, "' differently (", deckValue(earlier), " and ",
                        deckValue(entry), ")");
        }
      }
    }
  }
  names_.push_back(name);
  methods_.emplace(name, std::move(info));
}

bool MethodRegistry::has(const std::string& name) const
{
  return methods_.count(name) > 0;
}

const MethodInfo& MethodRegistry::info(const std::string& name) const
{
  const auto found = methods_.find(name);
  if (found != methods_.end()) {
    return found->second;
  }
  const auto closest = core::closestMatch(name, names_);
  throw core::InputError(core::message("'", methodKey, "' = '", name,
                                       "': there is no time-integration method by that name; registered: ",
                                       joined(names_, ", "), ".", closest ? " Did you mean '" + *closest + "'?" : ""));
}

std::unique_ptr<TimeIntegrationMethod> MethodRegistry::create(const TimeIntegrationSettings& settings) const
{
  const MethodInfo& chosen = info(settings.method);
  Teuchos::ParameterList keys = chosen.keys ? *chosen.keys : Teuchos::ParameterList("Time integration");
  const Teuchos::ParameterList& given = settings.methodParameters;
  for (auto it = given.begin(); it != given.end(); ++it) {
    const std::string& key = given.name(it);
    const Teuchos::ParameterEntry& value = given.entry(it);
    if (keys.isParameter(key)) {
      core::require<core::InputError>(sameType(value, keys.getEntry(key)), "'Time integration/", key,
                                      "' has the wrong type for Method ", settings.method, " (its default is ",
                                      deckValue(keys.getEntry(key)), ").");
      keys.getEntry(key).setAnyValue(value.getAny(false));
      continue;
    }
    std::vector<std::string> owners;
    const Teuchos::ParameterEntry* declared = nullptr;
    for (const auto& name : names_) {
      const auto& owned = methods_.at(name).keys;
      if (owned && owned->isParameter(key)) {
        owners.push_back(name);
        declared = &owned->getEntry(key);
      }
    }
    core::require<core::InputError>(declared != nullptr, "'Time integration/", key,
                                    "' is not a key of any time-integration method (registered: ", joined(names_, ", "),
                                    ").");
    core::require<core::InputError>(sameType(value, *declared) && value.getAny(false) == declared->getAny(false),
                                    "'Time integration/", key, "' = ", deckValue(value), " applies to Method ",
                                    joined(owners, ", "), " only ('", methodKey, "' is ", settings.method,
                                    "): leave it at its default ", deckValue(*declared), ".");
  }
  auto method = chosen.factory(settings, keys);
  core::require(static_cast<bool>(method), "internal: the factory of '", settings.method, "' made no method");
  return method;
}

void MethodRegistry::declareKeys(Teuchos::ParameterList& list) const
{
  for (const auto& name : names_) {
    const auto& keys = methods_.at(name).keys;
    if (!keys) {
      continue;
    }
    for (auto it = keys->begin(); it != keys->end(); ++it) {
      if (!list.isParameter(keys->name(it))) {
        list.setEntry(keys->name(it), keys->entry(it));
      }
    }
  }
}

} // namespace capsula::timeint
