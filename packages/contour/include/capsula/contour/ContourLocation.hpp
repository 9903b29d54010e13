#pragma once
// Points of a contour found by a property rather than by their parameter: the point at a
// given arc length from node 0, and the extreme points of the spline along an axis. Both
// return the segment and the local coordinate t in [0, 1] that Contour::pointAt takes.
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

/// The point where coordinate `axis` (0: x, 1: y) of the spline is smallest or largest
/// over the whole spline, not only the nodes (each cubic piece is checked at its ends and at
/// its stationary points), the first one on a tie; `value` is the coordinate there.
enum class Extreme { Smallest, Largest };
struct ContourExtremum {
  ContourLocation location;
  double value = 0.0;
};
ContourExtremum extremePoint(const Contour& contour, int axis, Extreme extreme);

/// The point of smallest y: extremePoint(contour, 1, Extreme::Smallest).location.
ContourLocation lowestPoint(const Contour& contour);

} // namespace capsula::contour
