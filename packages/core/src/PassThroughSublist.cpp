#include "capsula/core/PassThroughSublist.hpp"

#include "capsula/core/DeckValidators.hpp"
#include "capsula/core/Error.hpp"

#include <Teuchos_Array.hpp>

#include <vector>

namespace capsula::core {

namespace {

// Marks a valid list's sublist as passed through. The deck check (Deck.cpp) finds it on the
// entry and does not descend; Teuchos, which also validates the deck, is told not to descend
// by disableRecursiveValidation() and calls this only to ask that the entry is a sublist.
class PassThroughMarker final : public Teuchos::ParameterEntryValidator {
public:
  const std::string getXMLTypeName() const override { return "capsula::PassThroughSublist"; }
  void printDoc(const std::string& docString, std::ostream& out) const override { out << "# " << docString << "\n"; }
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override
  {
    require<InputError>(entry.isList(), "'", sublistName, "/", paramName, "' must be a sublist");
  }
};

// The type as a deck writes it, empty for a type a deck cannot hold (Belos's "Output
// Stream", an RCP<std::ostream>).
std::string deckTypeName(const Teuchos::ParameterEntry& entry)
{
  if (entry.isList()) {
    return "ParameterList";
  }
  if (entry.isType<int>()) {
    return "int";
  }
  if (entry.isType<double>()) {
    return "double";
  }
  if (entry.isType<bool>()) {
    return "bool";
  }
  if (entry.isType<std::string>()) {
    return "string";
  }
  if (entry.isType<Teuchos::Array<double>>()) {
    return "Array(double)";
  }
  if (entry.isType<Teuchos::Array<int>>()) {
    return "Array(int)";
  }
  if (entry.isType<Teuchos::Array<std::string>>()) {
    return "Array(string)";
  }
  return {};
}

std::string typeNameOf(const Teuchos::ParameterEntry& entry)
{
  const std::string name = deckTypeName(entry);
  return name.empty() ? entry.getAny(false).typeName() : name;
}

// The keys of `valid` a deck can set: those of a type a deck holds.
std::vector<std::string> settableNames(const Teuchos::ParameterList& valid)
{
  std::vector<std::string> names;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    if (!deckTypeName(valid.entry(it)).empty()) {
      names.push_back(valid.name(it));
    }
  }
  return names;
}

std::string quotedList(const std::vector<std::string>& names)
{
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "'" : ", '") + names[i] + "'";
  }
  return text.empty() ? "(none)" : text;
}

} // namespace

Teuchos::ParameterList& declarePassThroughSublist(Teuchos::ParameterList& list, const std::string& name,
                                                  const std::string& doc)
{
  Teuchos::ParameterList& sublist = list.sublist(name, false, doc);
  sublist.disableRecursiveValidation();
  list.getEntry(name).setValidator(Teuchos::rcp(new PassThroughMarker));
  return sublist;
}

bool isPassThroughSublist(const Teuchos::ParameterEntry& validEntry)
{
  return validEntry.isList() && dynamic_cast<const PassThroughMarker*>(validEntry.validator().get()) != nullptr;
}

void checkPassThroughEntries(Teuchos::ParameterList& entries, const Teuchos::ParameterList& valid,
                             const std::string& path, const std::string& owner)
{
  for (auto it = entries.begin(); it != entries.end(); ++it) {
    const std::string& name = entries.name(it);
    const std::string keyPath = path + "/" + name;
    Teuchos::ParameterEntry& entry = entries.getEntry(name);
    const Teuchos::ParameterEntry* validEntry = valid.getEntryPtr(name);
    if (validEntry == nullptr || deckTypeName(*validEntry).empty()) {
      std::string text = "'" + keyPath + "' is not a parameter of " + owner + ".";
      const std::vector<std::string> names = settableNames(valid);
      if (const auto guess = closestMatch(name, names)) {
        text += " Did you mean '" + path + "/" + *guess + "'?";
      }
      throw InputError(text + " The parameters a deck can set in '" + path + "': " + quotedList(names) + ".");
    }
    if (validEntry->isList() != entry.isList()) {
      throw InputError(message("'", keyPath, "' must be ", validEntry->isList() ? "a sublist" : "a value", " for ",
                               owner, ", not ", entry.isList() ? "a sublist" : "a value", "."));
    }
    if (entry.isList()) {
      checkPassThroughEntries(Teuchos::getValue<Teuchos::ParameterList>(entry),
                              Teuchos::getValue<Teuchos::ParameterList>(*validEntry), keyPath, owner);
      continue;
    }
    // An integer literal where a real is expected is what a user means: convert it.
    if (validEntry->isType<double>() && entry.isType<int>()) {
      entry.setValue(static_cast<double>(entry.getValue<int>(nullptr)));
    }
    require<InputError>(entry.getAny(false).type() == validEntry->getAny(false).type(), "'", keyPath, "' has type ",
                        typeNameOf(entry), " but ", owner, " takes a ", typeNameOf(*validEntry), ".");
    const auto validator = validEntry->validator();
    if (!validator.is_null()) {
      try {
        validator->validate(entry, name, path);
      } catch (const std::exception& e) {
        throw InputError("'" + keyPath + "' is refused by " + owner + ": " + lastLineOf(e.what()));
      }
    }
  }
}

} // namespace capsula::core
