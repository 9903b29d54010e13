#include "capsula/io/Json.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"
#include "capsula/io/NumberFormat.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace capsula::io {

namespace {

class JsonPrinter {
public:
  JsonPrinter(int indent, std::vector<std::string>* nonFinitePaths) : indent_(indent), nonFinitePaths_(nonFinitePaths)
  {}

  void print(const JsonValue& value, int depth, const std::string& path)
  {
    switch (value.kind()) {
    case JsonValue::Kind::Null:
      out_ << "null";
      break;
    case JsonValue::Kind::Boolean:
      out_ << (value.asBoolean() ? "true" : "false");
      break;
    case JsonValue::Kind::Integer:
      out_ << value.asInteger();
      break;
    case JsonValue::Kind::Number:
      if (std::isfinite(value.asNumber())) {
        // "2" would read back as an integer in most JSON libraries: keep it a number.
        const std::string text = shortestDecimal(value.asNumber());
        out_ << text << (text.find_first_of(".e") == std::string::npos ? ".0" : "");
      } else {
        out_ << "null";
        if (nonFinitePaths_ != nullptr) {
          nonFinitePaths_->push_back(path);
        }
      }
      break;
    case JsonValue::Kind::String:
      out_ << jsonQuoted(value.asString());
      break;
    case JsonValue::Kind::Array:
      printArray(value, depth, path);
      break;
    case JsonValue::Kind::Object:
      printObject(value, depth, path);
      break;
    }
  }

  std::string text() const { return out_.str(); }

private:
  void newline(int depth)
  {
    if (indent_ > 0) {
      out_ << '\n' << std::string(static_cast<std::size_t>(indent_ * depth), ' ');
    }
  }

  static std::string child(const std::string& path, const std::string& key)
  {
    return path.empty() ? key : path + "/" + key;
  }

  void printArray(const JsonValue& value, int depth, const std::string& path)
  {
    const auto& items = value.items();
    if (items.empty()) {
      out_ << "[]";
      return;
    }
    // Arrays of scalars stay on one line: time series read better that way.
    bool scalars = true;
    for (const auto& item : items) {
      scalars = scalars && item.kind() != JsonValue::Kind::Array && item.kind() != JsonValue::Kind::Object;
    }
    out_ << '[';
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (i > 0) {
        out_ << (scalars && indent_ > 0 ? ", " : ",");
      }
      if (!scalars) {
        newline(depth + 1);
      }
      print(items[i], depth + 1, child(path, std::to_string(i)));
    }
    if (!scalars) {
      newline(depth);
    }
    out_ << ']';
  }

  void printObject(const JsonValue& value, int depth, const std::string& path)
  {
    const auto& members = value.members();
    if (members.empty()) {
      out_ << "{}";
      return;
    }
    out_ << '{';
    for (std::size_t i = 0; i < members.size(); ++i) {
      if (i > 0) {
        out_ << ',';
      }
      newline(depth + 1);
      out_ << jsonQuoted(members[i].first) << (indent_ > 0 ? ": " : ":");
      print(members[i].second, depth + 1, child(path, members[i].first));
    }
    newline(depth);
    out_ << '}';
  }

  int indent_;
  std::vector<std::string>* nonFinitePaths_;
  std::ostringstream out_;
};

} // namespace

JsonValue::JsonValue(bool value) : kind_(Kind::Boolean), boolean_(value) {}
JsonValue::JsonValue(int value) : kind_(Kind::Integer), integer_(value) {}
JsonValue::JsonValue(long value) : kind_(Kind::Integer), integer_(value) {}
JsonValue::JsonValue(long long value) : kind_(Kind::Integer), integer_(value) {}
JsonValue::JsonValue(unsigned value) : kind_(Kind::Integer), integer_(value) {}
JsonValue::JsonValue(unsigned long value) : kind_(Kind::Integer), integer_(static_cast<std::int64_t>(value)) {}
JsonValue::JsonValue(double value) : kind_(Kind::Number), number_(value) {}
JsonValue::JsonValue(const char* value) : kind_(Kind::String), string_(value) {}
JsonValue::JsonValue(std::string value) : kind_(Kind::String), string_(std::move(value)) {}

JsonValue JsonValue::array()
{
  JsonValue v;
  v.kind_ = Kind::Array;
  return v;
}

JsonValue JsonValue::object()
{
  JsonValue v;
  v.kind_ = Kind::Object;
  return v;
}

JsonValue JsonValue::array(const std::vector<double>& values)
{
  JsonValue v = array();
  for (const double x : values) {
    v.items_.emplace_back(x);
  }
  return v;
}

JsonValue& JsonValue::operator[](const std::string& key)
{
  if (kind_ == Kind::Null) {
    kind_ = Kind::Object;
  }
  core::require(kind_ == Kind::Object, "internal: JSON member '", key, "' of a value that is not an object");
  for (auto& member : members_) {
    if (member.first == key) {
      return member.second;
    }
  }
  members_.emplace_back(key, JsonValue());
  return members_.back().second;
}

JsonValue& JsonValue::append(JsonValue value)
{
  if (kind_ == Kind::Null) {
    kind_ = Kind::Array;
  }
  core::require(kind_ == Kind::Array, "internal: appending to a JSON value that is not an array");
  items_.push_back(std::move(value));
  return *this;
}

std::string jsonQuoted(const std::string& text)
{
  std::string out = "\"";
  for (const char ch : text) {
    switch (ch) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\b':
      out += "\\b";
      break;
    case '\f':
      out += "\\f";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\r':
      out += "\\r";
      break;
    case '\t':
      out += "\\t";
      break;
    default:
      if (static_cast<unsigned char>(ch) < 0x20) {
        char escape[8];
        std::snprintf(escape, sizeof(escape), "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(ch)));
        out += escape;
      } else {
        out += ch; // UTF-8 passes through unchanged
      }
    }
  }
  return out + "\"";
}

std::string toJson(const JsonValue& value, int indent, std::vector<std::string>* nonFinitePaths)
{
  JsonPrinter printer(indent, nonFinitePaths);
  printer.print(value, 0, "");
  return printer.text();
}

void writeJsonFile(const std::string& path, const JsonValue& value)
{
  std::vector<std::string> nonFinite;
  std::string text = toJson(value, 2, &nonFinite);
  if (!nonFinite.empty() && value.kind() == JsonValue::Kind::Object) {
    JsonValue noted = value;
    JsonValue& list = noted["non_finite_written_as_null"];
    list = JsonValue::array();
    for (const auto& p : nonFinite) {
      list.append(p);
    }
    text = toJson(noted, 2, nullptr);
  }
  core::writeFileAtomically(path, [&](std::ostream& out) { out << text << '\n'; });
}

} // namespace capsula::io
