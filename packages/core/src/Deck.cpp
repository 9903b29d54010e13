#include "capsula/core/Deck.hpp"
#include "capsula/core/XmlText.hpp"

#include "DeckText.hpp"

#include "capsula/core/DeckValidators.hpp"
#include "capsula/core/Error.hpp"
#include "capsula/core/PassThroughSublist.hpp"

#include <Teuchos_ParameterEntryXMLConverterDB.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace capsula::core {

namespace {

std::string joinPath(const std::string& prefix, const std::string& name)
{
  return prefix.empty() ? name : prefix + "/" + name;
}

std::vector<std::string> namesIn(const Teuchos::ParameterList& list)
{
  std::vector<std::string> names;
  for (auto it = list.begin(); it != list.end(); ++it) {
    names.push_back(list.name(it));
  }
  return names;
}

std::string listOfNames(const std::vector<std::string>& names)
{
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : ", ") + ("'" + names[i] + "'");
  }
  return text.empty() ? "(none)" : text;
}

std::string typeNameOf(const Teuchos::ParameterEntry& entry)
{
  if (entry.isList()) {
    return "ParameterList";
  }
  const auto converter = Teuchos::ParameterEntryXMLConverterDB::getConverter(Teuchos::rcpFromRef(entry));
  return converter->getTypeAttributeValue();
}

void checkAgainst(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& path,
                  const std::string& deckName)
{
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string& name = deck.name(it);
    const std::string keyPath = joinPath(path, name);
    Teuchos::ParameterEntry& entry = deck.getEntry(name);
    const Teuchos::ParameterEntry* validEntry = valid.getEntryPtr(name);
    if (validEntry == nullptr) {
      std::string msg = "Deck '" + deckName + "': unknown key '" + keyPath + "'.";
      if (const auto guess = closestMatch(name, namesIn(valid))) {
        msg += " Did you mean '" + joinPath(path, *guess) + "'?";
      }
      msg += " Valid keys" + (path.empty() ? std::string(" at the top level") : " in '" + path + "'") + ": " +
             listOfNames(namesIn(valid)) + ".";
      throw InputError(msg);
    }
    if (validEntry->isList() != entry.isList()) {
      throw InputError(message("Deck '", deckName, "': '", keyPath, "' must be ",
                               validEntry->isList() ? "a ParameterList (sublist)" : "a Parameter (value)", ", not a ",
                               entry.isList() ? "sublist" : "value", "."));
    }
    if (isPassThroughSublist(*validEntry)) {
      continue; // its reader checks its entries (PassThroughSublist.hpp)
    }
    if (entry.isList()) {
      checkAgainst(Teuchos::getValue<Teuchos::ParameterList>(entry),
                   Teuchos::getValue<Teuchos::ParameterList>(*validEntry), keyPath, deckName);
      continue;
    }
    // An integer literal where a real is expected is what a user means: convert it.
    if (validEntry->isType<double>() && entry.isType<int>()) {
      entry.setValue(static_cast<double>(entry.getValue<int>(nullptr)));
    }
    if (entry.getAny(false).type() != validEntry->getAny(false).type()) {
      throw InputError(message("Deck '", deckName, "': '", keyPath, "' has type ", typeNameOf(entry),
                               " but must be of type ", typeNameOf(*validEntry), "."));
    }
    const auto validator = validEntry->validator();
    if (validator.is_null()) {
      continue;
    }
    if (const auto* described = dynamic_cast<const DescribedValidator*>(validator.get())) {
      const std::string why = described->check(entry);
      if (!why.empty()) {
        throw InputError("Deck '" + deckName + "': '" + keyPath + "' " + why + ".");
      }
    } else {
      try {
        validator->validate(entry, name, path);
      } catch (const std::exception& e) {
        throw InputError("Deck '" + deckName + "': '" + keyPath + "' is invalid: " + e.what());
      }
    }
  }
}

const Teuchos::ParameterEntry* findEntry(const Teuchos::ParameterList& list, const std::vector<std::string>& path)
{
  const Teuchos::ParameterList* current = &list;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (!current->isSublist(path[i])) {
      return nullptr;
    }
    current = &current->sublist(path[i]);
  }
  return current->getEntryPtr(path.back());
}

// Whether `path` names a key inside a pass-through sublist of `valid`.
bool insidePassThroughSublist(const Teuchos::ParameterList& valid, const std::vector<std::string>& path)
{
  const Teuchos::ParameterList* current = &valid;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Teuchos::ParameterEntry* entry = current->getEntryPtr(path[i]);
    if (entry == nullptr || !entry->isList()) {
      return false;
    }
    if (isPassThroughSublist(*entry)) {
      return true;
    }
    current = &Teuchos::getValue<Teuchos::ParameterList>(*entry);
  }
  return false;
}

// A --set value for a key no list declares (inside a pass-through sublist): typed by how its
// text reads, an integer, a real, true/false, otherwise a string. The reader's check
// converts an integer where it takes a real.
void setUntypedValue(Teuchos::ParameterList& list, const std::string& name, const std::string& text)
{
  int integer = 0;
  double real = 0.0;
  const std::string t = detail::trimmed(text);
  if (detail::parseInteger(t, integer)) {
    list.set(name, integer);
  } else if (detail::parseFiniteReal(t, real)) {
    list.set(name, real);
  } else if (t == "true" || t == "false") {
    list.set(name, t == "true");
  } else {
    list.set(name, text);
  }
}

std::vector<std::string> splitPath(const std::string& key)
{
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '/')) {
    parts.push_back(part);
  }
  return parts;
}

} // namespace

Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path)
{
  std::error_code notADirectory;
  if (std::filesystem::is_directory(path, notADirectory)) {
    throw IoError("Cannot read deck '" + path + "': it is a directory; give the deck's .xml file.");
  }
  std::ifstream in(path);
  if (!in) {
    throw IoError("Cannot read deck '" + path + "': the file does not exist or is not readable.");
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return readDeckFromString(buffer.str(), path);
}

Teuchos::RCP<Teuchos::ParameterList> readDeckFromString(const std::string& xml, const std::string& sourceName)
{
  detail::checkDeckText(xml, sourceName);
  Teuchos::RCP<Teuchos::ParameterList> deck;
  try {
    deck = Teuchos::getParametersFromXmlString(xml);
  } catch (const std::exception& e) {
    std::string what = e.what();
    // Teuchos prefixes its messages with a source location; keep the last line.
    const auto cut = what.find_last_of('\n', what.size() > 1 ? what.size() - 2 : 0);
    if (cut != std::string::npos) {
      what = what.substr(cut + 1);
    }
    throw InputError("Deck '" + sourceName + "' is not a valid Teuchos XML parameter list: " + detail::trimmed(what));
  }
  return deck;
}

void validateDeck(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& deckName)
{
  checkAgainst(deck, valid, "", deckName);
  try {
    deck.validateParametersAndSetDefaults(valid);
  } catch (const std::exception& e) {
    throw InputError("Deck '" + deckName + "' failed validation: " + std::string(e.what()));
  }
}

void applyOverride(Teuchos::ParameterList& deck, const Teuchos::ParameterList& valid, const std::string& assignment)
{
  const auto eq = assignment.find('=');
  require<InputError>(eq != std::string::npos && eq > 0, "--set \"", assignment,
                      "\": expected \"List/Sub/Key=value\", e.g. --set \"Flow/Capillary number=0.3\".");
  const std::string key = detail::trimmed(assignment.substr(0, eq));
  const std::string text = assignment.substr(eq + 1);
  const auto path = splitPath(key);
  const Teuchos::ParameterEntry* target = findEntry(valid, path);
  if (target == nullptr) {
    target = findEntry(deck, path);
  }
  if (target == nullptr && insidePassThroughSublist(valid, path)) {
    Teuchos::ParameterList* list = &deck;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      list = &list->sublist(path[i]);
    }
    setUntypedValue(*list, path.back(), assignment.substr(eq + 1));
    return;
  }
  if (target == nullptr || target->isList()) {
    std::string msg = "--set \"" + assignment + "\": '" + key + "' is not a parameter of this app.";
    // Suggest a sibling key if the parent list exists.
    std::vector<std::string> parent(path.begin(), path.end() - 1);
    const Teuchos::ParameterList* list = &valid;
    for (const auto& p : parent) {
      list = list->isSublist(p) ? &list->sublist(p) : nullptr;
      if (list == nullptr) {
        break;
      }
    }
    if (list != nullptr) {
      if (const auto guess = closestMatch(path.back(), namesIn(*list))) {
        std::vector<std::string> fixed = parent;
        fixed.push_back(*guess);
        std::string suggestion;
        for (std::size_t i = 0; i < fixed.size(); ++i) {
          suggestion += (i ? "/" : "") + fixed[i];
        }
        msg += " Did you mean '" + suggestion + "'?";
      }
    }
    msg += " Run with --print-defaults to see every key.";
    throw InputError(msg);
  }

  Teuchos::ParameterList* list = &deck;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    list = &list->sublist(path[i]);
  }
  const std::string& name = path.back();
  const auto bad = [&](const std::string& expected) {
    return InputError("--set \"" + assignment + "\": '" + text + "' is not " + expected + ".");
  };
  if (target->isType<double>()) {
    double v = 0.0;
    if (!detail::parseFiniteReal(text, v)) {
      throw bad("a finite real number");
    }
    list->set(name, v);
  } else if (target->isType<int>()) {
    int v = 0;
    if (!detail::parseInteger(text, v)) {
      throw bad("an integer");
    }
    list->set(name, v);
  } else if (target->isType<bool>()) {
    const std::string t = detail::trimmed(text);
    if (t == "true" || t == "1" || t == "yes" || t == "on") {
      list->set(name, true);
    } else if (t == "false" || t == "0" || t == "no" || t == "off") {
      list->set(name, false);
    } else {
      throw bad("a boolean (true/false)");
    }
  } else if (target->isType<std::string>()) {
    list->set(name, text);
  } else if (target->isType<Teuchos::Array<double>>()) {
    std::string t = detail::trimmed(text);
    if (!t.empty() && t.front() == '{' && t.back() == '}') {
      t = t.substr(1, t.size() - 2);
    }
    Teuchos::Array<double> values;
    std::istringstream in(t);
    std::string item;
    while (std::getline(in, item, ',')) {
      double v = 0.0;
      if (!detail::parseFiniteReal(item, v)) {
        throw bad("a list of finite real numbers such as {0, 2.5, 0}");
      }
      values.push_back(v);
    }
    list->set(name, values);
  } else {
    throw InputError("--set \"" + assignment + "\": parameters of type " + typeNameOf(*target) +
                     " cannot be set from the command line; edit the deck.");
  }
}

namespace {

// The shortest decimal text that reads back as exactly the same double.
std::string shortestReal(double v)
{
  char buffer[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, v);
    if (std::strtod(buffer, nullptr) == v) {
      break;
    }
  }
  return buffer;
}

std::string commentSafe(std::string s)
{
  // "--" may not appear inside an XML comment.
  for (auto pos = s.find("--"); pos != std::string::npos; pos = s.find("--")) {
    s.replace(pos, 2, "- -");
  }
  return s;
}

void writeList(std::ostream& out, const Teuchos::ParameterList& list, const std::string& name, bool withDocs, int depth)
{
  const std::string indent(static_cast<std::size_t>(2 * depth), ' ');
  out << indent << "<ParameterList name=\"" << xmlEscaped(name) << "\">\n";
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& key = list.name(it);
    const Teuchos::ParameterEntry& entry = list.entry(it);
    const std::string inner(static_cast<std::size_t>(2 * depth + 2), ' ');
    if (withDocs) {
      std::string doc = entry.docString();
      if (!entry.isList() && !entry.validator().is_null()) {
        if (const auto* d = dynamic_cast<const DescribedValidator*>(entry.validator().get())) {
          doc += (doc.empty() ? "" : " ") + std::string("Must be ") + d->requirement() + ".";
        }
      }
      if (!doc.empty()) {
        out << inner << "<!-- " << commentSafe(doc) << " -->\n";
      }
    }
    if (entry.isList()) {
      writeList(out, Teuchos::getValue<Teuchos::ParameterList>(entry), key, withDocs, depth + 1);
    } else {
      const auto converter = Teuchos::ParameterEntryXMLConverterDB::getConverter(Teuchos::rcpFromRef(entry));
      std::string value;
      if (entry.isType<double>()) {
        value = shortestReal(entry.getValue<double>(nullptr));
      } else if (entry.isType<Teuchos::Array<double>>()) {
        const auto& a = entry.getValue<Teuchos::Array<double>>(nullptr);
        value = "{";
        for (Teuchos::Array<double>::size_type i = 0; i < a.size(); ++i) {
          value += (i ? ", " : "") + shortestReal(a[i]);
        }
        value += "}";
      } else {
        value = converter->getValueAttributeValue(Teuchos::rcpFromRef(entry));
      }
      out << inner << "<Parameter name=\"" << xmlEscaped(key) << "\" type=\"" << converter->getTypeAttributeValue()
          << "\" value=\"" << xmlEscaped(value) << "\"/>\n";
    }
  }
  out << indent << "</ParameterList>\n";
}

} // namespace

void writeDeckXml(std::ostream& out, const Teuchos::ParameterList& list, bool withDocs)
{
  const std::string name = list.name().empty() ? "ANONYMOUS" : list.name();
  writeList(out, list, name, withDocs, 0);
}

std::string deckToXml(const Teuchos::ParameterList& list, bool withDocs)
{
  std::ostringstream out;
  out.precision(17);
  writeDeckXml(out, list, withDocs);
  return out.str();
}

} // namespace capsula::core
