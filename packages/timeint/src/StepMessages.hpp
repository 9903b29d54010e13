#pragma once
// What the explicit and the linearly implicit steps share: how they print times in
// messages, and when a step is stretched onto the stop time.
#include <sstream>
#include <string>

namespace capsula::timeint::detail {

/// Times and step sizes in messages: enough digits to tell nearby times apart.
inline std::string shown(double value)
{
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

/// A step ending within this fraction beyond the stop time is stretched onto it rather
/// than followed by a sliver step.
constexpr double stretchFraction = 0.01;

} // namespace capsula::timeint::detail
