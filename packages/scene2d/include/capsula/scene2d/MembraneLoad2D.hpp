#pragma once
// Load of a 2D membrane on the fluids (thesis eq A.4).
//
// Sign convention (the 3D ERRATA's): Delta f = (sigma_ext - sigma_int) . n with n the
// outward normal. Equilibrium of a membrane element, Delta f + d(gamma t)/dl = 0, with
// dt/dl = -kappa n (capsula::contour conventions) gives
//     Delta f = gamma kappa n - (d gamma / dl) t.
// An inflated circle (gamma > 0, kappa = 1/R) gets Delta f = (gamma / R) n, i.e.
// p_int - p_ext = gamma / R: the Laplace law with the higher pressure inside.
#include <capsula/contour/Contour.hpp>

#include <Eigen/Core>

namespace capsula::scene2d {

/// Delta f = gamma kappa n - (d gamma / dl) t at one point of the contour.
inline Eigen::Vector2d membraneLoad2D(double tension, double tensionSlope, const contour::ContourPoint& point)
{
  return tension * point.curvature * point.normal - tensionSlope * point.tangent;
}

} // namespace capsula::scene2d
