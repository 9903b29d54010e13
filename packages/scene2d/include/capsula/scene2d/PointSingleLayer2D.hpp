#pragma once
// A dense, cheap stand-in for the 2D single layer at the nodes (LayerPotentials2D.hpp):
//   SL_j(x_t) = int_C f_i G_ij(x, x_t) dl  ~  sum_s M[2t + j][2s + i] f_i(x_s),
// each node s carrying its share of the arc length w_s = (l_{s-1} + l_s) / 2 (half of each
// segment it ends), as a point force for every other node:
//   M[2t + j][2s + i] = w_s G_ij(x_s, x_t)   (s != t),
// and its own share integrated along its tangent, from -l_{t-1}/2 to l_t/2, where the
// free-space Stokeslet -delta_ij ln|s| + t_i t_j is integrated exactly and the wall's
// images (regular there) by Gauss-Legendre. Its error is first order in the node spacing
// for smooth loads, against the spectral accuracy of the spline quadrature; it is meant
// for preconditioners (scene2d::VelocityJacobian2D), where a dense matrix with the right
// long-range coupling and the right grid-scale response matters more than its accuracy.
// N^2 Green's function evaluations.
#include <capsula/contour/Contour.hpp>

#include <Eigen/Core>

namespace capsula::scene2d {

/// M (2N x 2N, row 2t + j, column 2s + i) for `contour`, with the plane wall y = 0's
/// images (`wall`) or in free space.
Eigen::MatrixXd pointSingleLayer2D(const contour::Contour& contour, bool wall);

} // namespace capsula::scene2d
