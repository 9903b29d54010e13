#pragma once
// Exact curvature of the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 (body axes), the
// reference the curvature estimates are measured against (thesis Fig. 5.23).
// Sign convention of ElementCurvature.hpp: outward normal, kappa = 1/R on a sphere.
#include <capsula/mesh/ElementCurvature.hpp>
#include <capsula/mesh/Vec3.hpp>

#include <cmath>

namespace capsula::mesh {

/// Outward unit normal at a point of the ellipsoid: grad(x^2/a^2 + ...) normalised.
inline Vec3 ellipsoidNormal(const Vec3& semiAxes, const Vec3& point)
{
  return point.cwiseQuotient(semiAxes.cwiseProduct(semiAxes)).normalized();
}

/// Mean and Gaussian curvature at a point of the ellipsoid. With
/// s = x^2/a^4 + y^2/b^4 + z^2/c^4 (|grad|^2 / 4):
///   K     = 1 / (a^2 b^2 c^2 s^2),
///   kappa = (a^2 + b^2 + c^2 - |x|^2) / (2 a^2 b^2 c^2 s^(3/2)),
/// which give c/a^2 and c/b^2 as the principal curvatures at the pole (0, 0, c).
inline CurvaturePair ellipsoidCurvature(const Vec3& semiAxes, const Vec3& point)
{
  const Vec3 a2 = semiAxes.cwiseProduct(semiAxes);
  const double s = point.cwiseQuotient(a2).squaredNorm();
  const double abc2 = a2[0] * a2[1] * a2[2];
  return {(a2.sum() - point.squaredNorm()) / (2.0 * abc2 * std::pow(s, 1.5)), 1.0 / (abc2 * s * s)};
}

} // namespace capsula::mesh
