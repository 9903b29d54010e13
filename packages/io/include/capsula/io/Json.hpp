#pragma once
// A minimal JSON document builder and writer for run summaries (summary.json):
//
//   io::JsonValue summary = io::JsonValue::object();
//   summary["cells"] = 2;
//   summary["D12"]["max"] = 0.538;            // nested objects are created on use
//   summary["times"].append(0.5).append(1.0);  // so are arrays
//   io::writeJsonFile(dir + "/summary.json", summary);
//
// Objects keep their keys in insertion order. Doubles are written in the shortest form
// that reads back exactly, with ".0" added to integral ones ("2.0") so that readers keep
// them floating point; integers exactly. JSON has no NaN or infinity: a non-finite
// number is written as null, and writeJsonFile notes where under the top-level key
// "non_finite_written_as_null" (a list of paths such as "D12/max") when the document is
// an object. Strings are escaped per RFC 8259 (quote, backslash, control characters).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace capsula::io {

class JsonValue {
public:
  enum class Kind { Null, Boolean, Integer, Number, String, Array, Object };

  JsonValue() = default; ///< null
  JsonValue(bool value);
  JsonValue(int value);
  JsonValue(long value);
  JsonValue(long long value);
  JsonValue(unsigned value);
  JsonValue(unsigned long value);
  JsonValue(double value);
  JsonValue(const char* value);
  JsonValue(std::string value);

  static JsonValue array();
  static JsonValue object();
  /// An array of numbers.
  static JsonValue array(const std::vector<double>& values);

  Kind kind() const { return kind_; }

  /// Object member access; a null value becomes an object, a missing key is added (null).
  JsonValue& operator[](const std::string& key);
  /// Appends to an array (a null value becomes an array); returns *this for chaining.
  JsonValue& append(JsonValue value);

  bool asBoolean() const { return boolean_; }
  std::int64_t asInteger() const { return integer_; }
  double asNumber() const { return number_; }
  const std::string& asString() const { return string_; }
  const std::vector<JsonValue>& items() const { return items_; }
  const std::vector<std::pair<std::string, JsonValue>>& members() const { return members_; }

private:
  Kind kind_ = Kind::Null;
  bool boolean_ = false;
  std::int64_t integer_ = 0;
  double number_ = 0.0;
  std::string string_;
  std::vector<JsonValue> items_;
  std::vector<std::pair<std::string, JsonValue>> members_;
};

/// The JSON text, indented by `indent` spaces per level (0: one line). Paths of
/// non-finite numbers written as null are added to `nonFinitePaths` if given.
std::string toJson(const JsonValue& value, int indent = 2, std::vector<std::string>* nonFinitePaths = nullptr);

/// "\"text\"" with JSON escapes.
std::string jsonQuoted(const std::string& text);

/// Writes the document to `path` atomically (see above for non-finite numbers).
/// Throws core::IoError naming the file.
void writeJsonFile(const std::string& path, const JsonValue& value);

} // namespace capsula::io
