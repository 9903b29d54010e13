#include "DeckText.hpp"

#include "capsula/core/Error.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

namespace capsula::core::detail {

namespace {

/// One tag of the deck's text, as far as the check needs it.
struct Tag {
  std::string element;                           // "ParameterList", "Parameter", ...
  std::map<std::string, std::string> attributes; // as written (numbers hold no entities)
  bool closing = false;                          // </ParameterList>
  bool selfClosing = false;                      // <ParameterList .../> or <Parameter .../>
  int line = 1;
};

/// Reads the attributes of a start tag's text (after the element name).
std::map<std::string, std::string> attributesOf(const std::string& text)
{
  std::map<std::string, std::string> attributes;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto eq = text.find('=', i);
    if (eq == std::string::npos) {
      break;
    }
    const std::string name = trimmed(text.substr(i, eq - i));
    const auto open = text.find_first_of("\"'", eq + 1);
    if (open == std::string::npos) {
      break;
    }
    const auto close = text.find(text[open], open + 1);
    if (close == std::string::npos) {
      break;
    }
    attributes[name] = text.substr(open + 1, close - open - 1);
    i = close + 1;
  }
  return attributes;
}

/// The tags of a well-formed deck in document order, with their line numbers; comments,
/// the XML declaration and processing instructions are skipped.
std::vector<Tag> tagsOf(const std::string& xml)
{
  std::vector<Tag> tags;
  int line = 1;
  std::size_t i = 0;
  const auto advanceTo = [&](std::size_t end) {
    for (; i < end && i < xml.size(); ++i) {
      line += xml[i] == '\n' ? 1 : 0;
    }
  };
  while (true) {
    const auto open = xml.find('<', i);
    if (open == std::string::npos) {
      break;
    }
    advanceTo(open);
    if (xml.compare(open, 4, "<!--") == 0) {
      advanceTo(xml.find("-->", open) + 3);
      continue;
    }
    // The tag ends at the first '>' outside quotes (XML allows '>' inside attribute values).
    std::size_t close = open + 1;
    for (char quote = 0; close < xml.size() && (quote != 0 || xml[close] != '>'); ++close) {
      if (quote == 0 && (xml[close] == '"' || xml[close] == '\'')) {
        quote = xml[close];
      } else if (xml[close] == quote) {
        quote = 0;
      }
    }
    if (close >= xml.size()) {
      break;
    }
    std::string body = xml.substr(open + 1, close - open - 1);
    Tag tag;
    tag.line = line;
    advanceTo(close + 1);
    if (body.empty() || body.front() == '?' || body.front() == '!') {
      continue;
    }
    if (body.front() == '/') {
      tag.closing = true;
      body.erase(0, 1);
    }
    if (!body.empty() && body.back() == '/') {
      tag.selfClosing = true;
      body.pop_back();
    }
    const auto nameEnd = body.find_first_of(" \t\r\n");
    tag.element = body.substr(0, nameEnd);
    if (nameEnd != std::string::npos) {
      tag.attributes = attributesOf(body.substr(nameEnd));
    }
    tags.push_back(tag);
  }
  return tags;
}

std::string valueProblem(const std::string& type, const std::string& value)
{
  double real = 0.0;
  int integer = 0;
  bool boolean = false;
  if (type == "double" || type == "float") {
    return parseFiniteReal(value, real) ? "" : "is not a finite real number";
  }
  if (type == "int") {
    return parseInteger(value, integer) ? "" : "is not an integer (whole number from -2147483648 to 2147483647)";
  }
  if (type == "bool") {
    return parseBoolean(value, boolean) ? "" : "is not a boolean (true or false)";
  }
  if (type == "Array(double)" || type == "Array(int)") {
    std::string inner = trimmed(value);
    if (inner.size() < 2 || inner.front() != '{' || inner.back() != '}') {
      return "is not an array written as {a, b, c}";
    }
    inner = inner.substr(1, inner.size() - 2);
    if (trimmed(inner).empty()) {
      return "";
    }
    std::istringstream in(inner);
    std::string item;
    int position = 1;
    const bool reals = type == "Array(double)";
    while (std::getline(in, item, ',')) {
      if (reals ? !parseFiniteReal(item, real) : !parseInteger(item, integer)) {
        return message("has element ", position, " = \"", trimmed(item), "\", which is not ",
                       reals ? "a finite real number" : "an integer");
      }
      ++position;
    }
    return inner.back() == ',' ? "ends with a comma" : "";
  }
  return "";
}

std::string joined(const std::vector<std::string>& path, const std::string& name)
{
  std::string key;
  for (const auto& part : path) {
    key += part + "/";
  }
  return key + name;
}

} // namespace

std::string trimmed(const std::string& s)
{
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) {
    return {};
  }
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

bool parseFiniteReal(const std::string& text, double& value)
{
  const std::string t = trimmed(text);
  if (t.empty()) {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  return errno == 0 && end == t.c_str() + t.size() && std::isfinite(value);
}

bool parseInteger(const std::string& text, int& value)
{
  const std::string t = trimmed(text);
  if (t.empty()) {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (errno != 0 || end != t.c_str() + t.size() || v < INT_MIN || v > INT_MAX) {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool parseBoolean(const std::string& text, bool& value)
{
  // The spellings Teuchos's XML reader accepts, in any case.
  std::string t = trimmed(text);
  for (char& c : t) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (t == "true" || t == "yes" || t == "1") {
    value = true;
    return true;
  }
  if (t == "false" || t == "no" || t == "0") {
    value = false;
    return true;
  }
  return false;
}

void checkDeckText(const std::string& xml, const std::string& sourceName)
{
  // The open lists below the deck's own top-level list, and the line of every key seen in each.
  std::vector<std::string> path;
  std::vector<std::map<std::string, int>> seen;
  int depth = 0;
  for (const Tag& tag : tagsOf(xml)) {
    if (tag.element != "ParameterList" && tag.element != "Parameter") {
      continue;
    }
    if (tag.closing) {
      if (tag.element == "ParameterList" && depth > 0) {
        --depth;
        if (!path.empty() && depth > 0) {
          path.pop_back();
        }
        seen.pop_back();
      }
      continue;
    }
    const auto nameIt = tag.attributes.find("name");
    const std::string name = nameIt == tag.attributes.end() ? "" : nameIt->second;
    if (depth > 0) {
      const auto [previous, fresh] = seen.back().emplace(name, tag.line);
      require<InputError>(fresh, "Deck '", sourceName, "': '", joined(path, name), "' is given twice (lines ",
                          previous->second, " and ", tag.line, "); keep one.");
    }
    if (tag.element == "Parameter") {
      const auto type = tag.attributes.find("type");
      const auto value = tag.attributes.find("value");
      if (type != tag.attributes.end() && value != tag.attributes.end()) {
        const std::string problem = valueProblem(type->second, value->second);
        require<InputError>(problem.empty(), "Deck '", sourceName, "', line ", tag.line, ": '", joined(path, name),
                            "' = \"", value->second, "\" ", problem, ".");
      }
      continue;
    }
    if (!tag.selfClosing) {
      if (depth > 0) {
        path.push_back(name);
      }
      ++depth;
      seen.emplace_back();
    }
  }
}

} // namespace capsula::core::detail
