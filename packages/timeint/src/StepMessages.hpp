#pragma once
// What the explicit and the linearly implicit steps share: how they print times in
// messages, and when a step is stretched onto the stop time.
#include "capsula/core/Error.hpp"
#include "capsula/timeint/VectorNorms.hpp"

#include <sstream>
#include <string>
#include <vector>

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

/// Stops the run when a step of `method` from tFrom with step h produced a non-finite
/// state for tNew (the state at tFrom stays the last accepted one).
inline void requireFiniteNewState(const std::vector<double>& y, double tNew, const std::string& method, double tFrom,
                                  double h)
{
  const std::size_t n = y.size();
  const std::size_t bad = firstNonFinite(y.data(), n);
  if (bad != n) {
    throw core::NumericalError(
        core::message("Time integration failed: the new state is not finite at t = ", shown(tNew), " (entry ", bad,
                      " of ", n, "; ", method, " step from t = ", shown(tFrom), " with dt = ", shown(h),
                      "). The state at t = ", shown(tFrom), " is the last accepted one."));
  }
}

} // namespace capsula::timeint::detail
