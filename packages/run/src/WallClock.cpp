#include "capsula/run/WallClock.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace capsula::run {

std::string wallClock(double seconds)
{
  if (!std::isfinite(seconds) || seconds < 0.0) {
    return "?";
  }
  const long s = std::lround(seconds);
  std::ostringstream out;
  out << s / 3600 << ":" << std::setw(2) << std::setfill('0') << (s / 60) % 60 << ":" << std::setw(2)
      << std::setfill('0') << s % 60;
  return out.str();
}

double timeLeft(double spent, double start, double now, double end)
{
  const double done = now - start;
  return done > 0.0 ? spent / done * (end - now) : std::numeric_limits<double>::quiet_NaN();
}

} // namespace capsula::run
