#include "capsula/contour/ContourLocation.hpp"

#include <capsula/core/Error.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace capsula::contour {

ContourLocation locateArcLength(const Contour& contour, double arcLength)
{
  core::require<core::InputError>(std::isfinite(arcLength), "locateArcLength: the arc length is ", arcLength);
  const double total = contour.length();
  double l = arcLength;
  if (contour.closure() == Closure::Periodic) {
    l = std::fmod(l, total);
    if (l < 0.0) {
      l += total;
    }
  } else {
    l = std::clamp(l, 0.0, total);
  }
  const std::vector<double>& knots = contour.knotArcLengths();
  // The segment k with l_k <= l < l_{k+1} (the last one for l = length()).
  const auto upper = std::upper_bound(knots.begin(), knots.end(), l);
  const int segment = std::clamp(static_cast<int>(upper - knots.begin()) - 1, 0, contour.numberOfSegments() - 1);
  const auto k = static_cast<std::size_t>(segment);
  const double start = knots[k];
  const double span = knots[k + 1] - start;
  // Newton on g(t) = arcLengthAt(k, t) - l, g' = h (s_{k+1} - s_k) > 0; the initial guess
  // from the chord is within O(h^2) of the root, so a few steps reach round-off.
  const std::vector<double>& s = contour.parameters();
  const double parameterSpan = s[k + 1] - s[k];
  double t = span > 0.0 ? (l - start) / span : 0.0;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double residual = contour.arcLengthAt(segment, t) - l;
    const double slope = contour.pointAt(segment, t).metric * parameterSpan;
    const double step = residual / slope;
    t = std::clamp(t - step, 0.0, 1.0);
    if (std::abs(step) < 1e-15) {
      break;
    }
  }
  return {segment, t};
}

ContourExtremum extremePoint(const Contour& contour, int axis, Extreme extreme)
{
  core::require<core::InputError>(axis == 0 || axis == 1, "extremePoint: axis must be 0 (x) or 1 (y), got ", axis);
  const CubicSpline& spline = axis == 0 ? contour.xSpline() : contour.ySpline();
  const std::vector<double>& s = spline.knots();
  const double sign = extreme == Extreme::Smallest ? 1.0 : -1.0; // the smallest of sign * value
  ContourExtremum best{{0, 0.0}, spline.piece(0).d};
  for (int k = 0; k < spline.numberOfPieces(); ++k) {
    const CubicPiece& piece = spline.piece(k);
    const auto index = static_cast<std::size_t>(k);
    const double span = s[index + 1] - s[index];
    double roots[2];
    const int count = stationaryPoints(piece, span, roots);
    // Candidates inside the piece and at its start (its end is the next piece's start; the
    // last piece's end is node 0 of a periodic contour, or the tether again).
    double candidates[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < count; ++i) {
      candidates[i + 1] = roots[i];
    }
    for (int i = 0; i <= count; ++i) {
      const double value = piece.value(candidates[i]);
      if (sign * value < sign * best.value) {
        best = {{k, candidates[i] / span}, value};
      }
    }
  }
  return best;
}

ContourLocation lowestPoint(const Contour& contour)
{
  return extremePoint(contour, 1, Extreme::Smallest).location;
}

} // namespace capsula::contour
