#pragma once
// Points of a contour found by a property rather than by their parameter: the point at a
// given arc length from node 0, and the lowest point of the spline. Both return the
// segment and the local coordinate t in [0, 1] that Contour::pointAt takes.
#include "capsula/contour/Contour.hpp"

namespace capsula::contour {

struct ContourLocation {
  int segment = 0;
  double t = 0.0;
};

/// The point whose arc length from node 0 is `arcLength` (periodic contours wrap it into
/// [0, length()); tethered ones clamp it to [0, length()]). Newton's method on
/// Contour::arcLengthAt within the segment that holds it, so the result is exact to
/// round-off for the contour's own arc-length rule.
ContourLocation locateArcLength(const Contour& contour, double arcLength);

/// The point of smallest y over the whole spline (each cubic piece of y(s) is checked at its
/// ends and at its stationary points), the first one on a tie.
ContourLocation lowestPoint(const Contour& contour);

} // namespace capsula::contour
