#include "capsula/io/NumberFormat.hpp"

#include <charconv>
#include <limits>
#include <system_error>

namespace capsula::io {

std::string shortestDecimal(double value)
{
  char buffer[32]; // the longest shortest form, "-2.2250738585072014e-308", has 24
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

bool parseDecimal(const std::string& text, double& value)
{
  if (text.empty()) {
    return false;
  }
  const bool negative = text[0] == '-';
  const std::string magnitude = negative ? text.substr(1) : text;
  if (magnitude == "nan" || magnitude == "inf") {
    value = magnitude == "nan" ? std::numeric_limits<double>::quiet_NaN() : std::numeric_limits<double>::infinity();
    value = negative ? -value : value;
    return true;
  }
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

} // namespace capsula::io
