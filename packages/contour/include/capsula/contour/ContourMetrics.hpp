#pragma once
// Shape metrics of a contour (thesis App. A.9.1 and eq 4.2), integrated exactly on the
// spline: every integrand below is a polynomial in s of degree <= 11 on each segment, so
// a 6-point Gauss-Legendre rule per segment leaves only round-off.
#include "capsula/contour/Contour.hpp"

#include <Eigen/Core>

namespace capsula::contour {

/// Area enclosed by the spline, 1/2 int (x dy - y dx).
double enclosedArea(const Contour& contour);

/// Area centroid: x_c = 1/(2A) int x^2 dy, y_c = -1/(2A) int y^2 dx.
Eigen::Vector2d centroid(const Contour& contour);

/// Second moment of area about the centroid, J = int_V (x - x_c)(x - x_c)^T dA, from
/// J_xx = 1/3 int X^3 dY, J_yy = -1/3 int Y^3 dX, J_xy = 1/2 int X^2 Y dY (X = x - x_c).
/// Eq A.54 prints the off-diagonal with a minus sign: that flips the principal
/// directions across the x-axis but leaves the eigenvalues, hence D12, unchanged.
Eigen::Matrix2d secondMomentOfArea(const Contour& contour);

/// The ellipse with the same area and second moment (eqs A.53-A.55): an ellipse of
/// semi-axes l_1, l_2 has eigenvalues A l_i^2 / 4, so l_i = 2 sqrt(lambda_i / A).
struct EquivalentEllipse {
  double majorSemiAxis = 0.0;
  double minorSemiAxis = 0.0;
  double orientation = 0.0; ///< angle of the major axis from the x-axis, in (-pi/2, pi/2]
};
EquivalentEllipse equivalentEllipse(const Contour& contour);

/// Taylor deformation D12 = (l_1 - l_2) / (l_1 + l_2) (eq A.53); (a - b)/(a + b) for an
/// ellipse of semi-axes a >= b.
double taylorDeformation(const Contour& contour);

struct Extent {
  double min = 0.0;
  double max = 0.0;
};
/// Extremes of x(s) (axis 0) or y(s) (axis 1) over the spline, not only the nodes: each
/// cubic piece is checked at its ends and at the roots of its derivative.
Extent extent(const Contour& contour, int axis);

/// Cell length in the flow direction, L_cell = x_max - x_min (eq 4.2).
double cellLength(const Contour& contour);

} // namespace capsula::contour
