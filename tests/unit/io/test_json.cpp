// JSON writer: exact text for a small document, escaping, round-trip numbers, NaN as
// null with a note; the pretty output is checked by an independent little parser.
#include "TemporaryDirectory.hpp"

#include "capsula/io/Json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace io = capsula::io;
using io::testing::TemporaryDirectory;

namespace {

/// A strict recursive-descent JSON parser (RFC 8259 subset: no \u surrogate pairs)
/// building an io::JsonValue; throws std::runtime_error on malformed text.
class JsonParser {
public:
  explicit JsonParser(std::string text) : text_(std::move(text)) {}

  io::JsonValue parseDocument()
  {
    io::JsonValue v = value();
    skipSpace();
    if (pos_ != text_.size()) {
      fail("trailing characters");
    }
    return v;
  }

private:
  [[noreturn]] void fail(const std::string& why)
  {
    throw std::runtime_error("JSON parse error at " + std::to_string(pos_) + ": " + why);
  }
  void skipSpace()
  {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\t' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }
  bool consume(const std::string& word)
  {
    if (text_.compare(pos_, word.size(), word) == 0) {
      pos_ += word.size();
      return true;
    }
    return false;
  }
  void expect(char c)
  {
    skipSpace();
    if (pos_ >= text_.size() || text_[pos_] != c) {
      fail(std::string("expected '") + c + "'");
    }
    ++pos_;
  }
  std::string string()
  {
    expect('"');
    std::string out;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      const char c = text_[pos_++];
      if (static_cast<unsigned char>(c) < 0x20) {
        fail("raw control character in a string");
      }
      if (c != '\\') {
        out += c;
        continue;
      }
      const char e = text_.at(pos_++);
      switch (e) {
      case '"':
        out += '"';
        break;
      case '\\':
        out += '\\';
        break;
      case '/':
        out += '/';
        break;
      case 'b':
        out += '\b';
        break;
      case 'f':
        out += '\f';
        break;
      case 'n':
        out += '\n';
        break;
      case 'r':
        out += '\r';
        break;
      case 't':
        out += '\t';
        break;
      case 'u': {
        const long code = std::strtol(text_.substr(pos_, 4).c_str(), nullptr, 16);
        if (code >= 0x80) {
          fail("non-ASCII \\u escape not expected from the writer");
        }
        out += static_cast<char>(code);
        pos_ += 4;
        break;
      }
      default:
        fail("bad escape");
      }
    }
    expect('"');
    return out;
  }
  io::JsonValue number()
  {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && std::string("+-0123456789.eE").find(text_[pos_]) != std::string::npos) {
      ++pos_;
    }
    const std::string token = text_.substr(start, pos_ - start);
    if (token.empty()) {
      fail("expected a value");
    }
    if (token.find_first_of(".eE") == std::string::npos) {
      return io::JsonValue(std::stoll(token));
    }
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (*end != '\0') {
      fail("bad number " + token);
    }
    return io::JsonValue(v);
  }
  io::JsonValue value()
  {
    skipSpace();
    if (pos_ >= text_.size()) {
      fail("unexpected end");
    }
    const char c = text_[pos_];
    if (c == '{') {
      ++pos_;
      io::JsonValue object = io::JsonValue::object();
      skipSpace();
      if (consume("}")) {
        return object;
      }
      do {
        skipSpace();
        const std::string key = string();
        expect(':');
        object[key] = value();
        skipSpace();
      } while (consume(","));
      expect('}');
      return object;
    }
    if (c == '[') {
      ++pos_;
      io::JsonValue array = io::JsonValue::array();
      skipSpace();
      if (consume("]")) {
        return array;
      }
      do {
        array.append(value());
        skipSpace();
      } while (consume(","));
      expect(']');
      return array;
    }
    if (c == '"') {
      return io::JsonValue(string());
    }
    if (consume("true")) {
      return io::JsonValue(true);
    }
    if (consume("false")) {
      return io::JsonValue(false);
    }
    if (consume("null")) {
      return io::JsonValue();
    }
    return number();
  }

  std::string text_;
  std::size_t pos_ = 0;
};

void expectSameValue(const io::JsonValue& a, const io::JsonValue& b, const std::string& path)
{
  ASSERT_EQ(static_cast<int>(a.kind()), static_cast<int>(b.kind())) << path;
  switch (a.kind()) {
  case io::JsonValue::Kind::Boolean:
    EXPECT_EQ(a.asBoolean(), b.asBoolean()) << path;
    break;
  case io::JsonValue::Kind::Integer:
    EXPECT_EQ(a.asInteger(), b.asInteger()) << path;
    break;
  case io::JsonValue::Kind::Number:
    EXPECT_EQ(a.asNumber(), b.asNumber()) << path;
    break; // exact
  case io::JsonValue::Kind::String:
    EXPECT_EQ(a.asString(), b.asString()) << path;
    break;
  case io::JsonValue::Kind::Array:
    ASSERT_EQ(a.items().size(), b.items().size()) << path;
    for (std::size_t i = 0; i < a.items().size(); ++i) {
      expectSameValue(a.items()[i], b.items()[i], path + "/" + std::to_string(i));
    }
    break;
  case io::JsonValue::Kind::Object:
    ASSERT_EQ(a.members().size(), b.members().size()) << path;
    for (std::size_t i = 0; i < a.members().size(); ++i) {
      EXPECT_EQ(a.members()[i].first, b.members()[i].first) << path;
      expectSameValue(a.members()[i].second, b.members()[i].second, path + "/" + a.members()[i].first);
    }
    break;
  case io::JsonValue::Kind::Null:
    break;
  }
}

io::JsonValue sampleDocument()
{
  io::JsonValue doc = io::JsonValue::object();
  doc["application"] = "cell3d";
  doc["cells"] = 2;
  doc["steps"] = static_cast<long long>(9007199254740993LL); // > 2^53: must stay exact
  doc["converged"] = true;
  doc["D12"]["max"] = 0.538;
  doc["D12"]["time of max"] = 1.0 / 3.0;
  doc["times"] = io::JsonValue::array({0.1, 0.2, 1e-12, -3.5e300});
  doc["note"] = "tab\there, \"quoted\", back\\slash, line\nbreak, bell\x07, micro\xc2\xb5m";
  doc["empty list"] = io::JsonValue::array();
  doc["empty object"] = io::JsonValue::object();
  doc["nothing"] = io::JsonValue();
  io::JsonValue cell = io::JsonValue::object();
  cell["name"] = "cell 0";
  cell["centroid"] = io::JsonValue::array({0.0, 2.0, 0.0});
  doc["per cell"].append(cell).append(cell);
  return doc;
}

} // namespace

TEST(Json, CompactTextIsExact)
{
  io::JsonValue doc = io::JsonValue::object();
  doc["a"] = 1;
  doc["b"] = io::JsonValue::array({1.0, 2.5});
  doc["s"] = "q\"\\\n\x01";
  doc["n"] = io::JsonValue();
  doc["t"] = true;
  doc["o"] = io::JsonValue::object();
  doc["a"] = 2; // assigning an existing key replaces it in place
  EXPECT_EQ(io::toJson(doc, 0), R"({"a":2,"b":[1.0,2.5],"s":"q\"\\\n\u0001","n":null,"t":true,"o":{}})");
}

TEST(Json, PrettyOutputParsesBackToTheSameDocument)
{
  const io::JsonValue doc = sampleDocument();
  const std::string text = io::toJson(doc);
  const io::JsonValue parsed = JsonParser(text).parseDocument();
  expectSameValue(parsed, doc, "");
  EXPECT_TRUE(io::testing::contains(text, "\"times\": [0.1, 0.2, 1e-12, -3.5e+300]")) << text;
}

TEST(Json, NonFiniteNumbersAreWrittenAsNullWithANote)
{
  TemporaryDirectory dir("json_nan");
  io::JsonValue doc = io::JsonValue::object();
  doc["D12"]["max"] = std::numeric_limits<double>::quiet_NaN();
  doc["series"] = io::JsonValue::array({1.0, std::numeric_limits<double>::infinity()});
  const std::string path = dir.file("summary.json");
  io::writeJsonFile(path, doc);
  const io::JsonValue parsed = JsonParser(io::testing::readText(path)).parseDocument();
  const auto& members = parsed.members();
  ASSERT_EQ(members.size(), 3u);
  EXPECT_EQ(members[0].second.members()[0].second.kind(), io::JsonValue::Kind::Null);
  EXPECT_EQ(members[1].second.items()[1].kind(), io::JsonValue::Kind::Null);
  EXPECT_EQ(members[2].first, "non_finite_written_as_null");
  ASSERT_EQ(members[2].second.items().size(), 2u);
  EXPECT_EQ(members[2].second.items()[0].asString(), "D12/max");
  EXPECT_EQ(members[2].second.items()[1].asString(), "series/1");
  EXPECT_EQ(dir.entryCount(), 1u); // no temporary left
}

TEST(Json, TheTestParserRejectsMalformedText)
{
  // The checks above rely on this parser being strict.
  EXPECT_THROW(JsonParser(R"({"a":1,})").parseDocument(), std::runtime_error);
  EXPECT_THROW(JsonParser(R"({"a" 1})").parseDocument(), std::runtime_error);
  EXPECT_THROW(JsonParser("[1, 2").parseDocument(), std::runtime_error);
  EXPECT_THROW(JsonParser("\"raw\nbreak\"").parseDocument(), std::runtime_error);
  EXPECT_THROW(JsonParser("nan").parseDocument(), std::runtime_error);
}
