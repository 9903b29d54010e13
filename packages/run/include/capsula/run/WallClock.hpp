#pragma once
// Wall-clock time in progress lines: "h:mm:ss", and the estimate of the time left from the
// wall time per unit of simulated time so far.
#include <string>

namespace capsula::run {

/// "h:mm:ss" of `seconds` rounded; "?" for a negative or non-finite number.
std::string wallClock(double seconds);

/// The wall time left to reach `end` from `now` at the pace of `spent` wall seconds for
/// the simulated time from `start` to `now` (NaN before any progress).
double timeLeft(double spent, double start, double now, double end);

} // namespace capsula::run
