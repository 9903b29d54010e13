#pragma once
// The natural logarithm as straight-line arithmetic, so that a loop calling it vectorises
// (std::log is an opaque libm call: the 2D single layer has one logarithm per kernel pair
// and spent a third of its time in it).
//
// x = 2^e m with m in [sqrt(2)/2, sqrt(2)], read from the bits of x; then
//   ln x = e ln 2 + ln m,   ln m = 2 atanh(f) = 2 f (1 + f^2/3 + f^4/5 + ...),  f = (m-1)/(m+1),
// |f| <= 3 - 2 sqrt(2) = 0.1716, so f^2 <= 0.0295 and the series to f^20/21 leaves a
// truncation below 1e-18 relative. ln 2 is split into a high part with 21 trailing zero
// bits (e ln2hi is exact for |e| < 2^21) and the remainder. The result is within a few
// units in the last place of std::log (tests/unit/scene2d, VectorisableLog).
//
// Valid for finite, normal x > 0 only (no checks: the callers pass squared distances or
// their ratios, which are). The pieces are exposed so that a kernel can share the one
// division of the reduction with its own reciprocals.
#include <cstdint>
#include <cstring>

namespace capsula::operators {

/// x = 2^exponent mantissa with mantissa in [sqrt(2)/2, sqrt(2)] (exponent a whole number).
inline void centredMantissa(double x, double& exponent, double& mantissa)
{
  constexpr double sqrtTwo = 1.4142135623730951;
  constexpr std::uint64_t mantissaMask = 0x000FFFFFFFFFFFFFULL;
  constexpr std::uint64_t exponentOfOne = 0x3FF0000000000000ULL; // the bits of 1.0
  constexpr std::uint64_t twoPow52 = 0x4330000000000000ULL;      // the bits of 2^52

  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  // m in [1, 2): x's mantissa with the exponent of 1.
  const std::uint64_t mantissaBits = (bits & mantissaMask) | exponentOfOne;
  double m;
  std::memcpy(&m, &mantissaBits, sizeof m);
  // The biased exponent E (x > 0: no sign bit) as a double without an integer
  // conversion (none exists for 64-bit lanes before AVX-512): 2^52 + E, minus 2^52 + 1023.
  const std::uint64_t exponentBits = (bits >> 52) | twoPow52;
  double e;
  std::memcpy(&e, &exponentBits, sizeof e);
  e -= 4503599627370496.0 + 1023.0;
  const bool upper = m > sqrtTwo;
  mantissa = upper ? 0.5 * m : m;
  exponent = upper ? e + 1.0 : e;
}

/// e ln 2 + 2 atanh(f) for |f| <= 3 - 2 sqrt(2) (+ a few ulp): ln(2^e m) with f = (m-1)/(m+1).
inline double logFromReduced(double exponent, double f)
{
  constexpr double ln2High = 0.6931471803691238;    // 0x3fe62e42fee00000
  constexpr double ln2Low = 1.9082149292705877e-10; // ln 2 - ln2High
  const double s = f * f;
  double p = 1.0 / 21.0;
  p = p * s + 1.0 / 19.0;
  p = p * s + 1.0 / 17.0;
  p = p * s + 1.0 / 15.0;
  p = p * s + 1.0 / 13.0;
  p = p * s + 1.0 / 11.0;
  p = p * s + 1.0 / 9.0;
  p = p * s + 1.0 / 7.0;
  p = p * s + 1.0 / 5.0;
  p = p * s + 1.0 / 3.0;
  // 2 f (1 + s p) = 2 f + 2 f s p: the leading term kept apart for accuracy.
  const double twoF = 2.0 * f;
  return exponent * ln2High + (exponent * ln2Low + (twoF + twoF * s * p));
}

inline double vectorisableLog(double x)
{
  double e, m;
  centredMantissa(x, e, m);
  return logFromReduced(e, (m - 1.0) / (m + 1.0));
}

} // namespace capsula::operators
