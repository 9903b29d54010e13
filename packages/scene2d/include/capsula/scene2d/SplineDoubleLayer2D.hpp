#pragma once
// The 2D double layer at the node targets as a linear map of the density's spline data,
// built once per geometry and applied by every GMRES iteration (InterfaceVelocity2D).
//
// The density u is splined along the contour (ContourField2D: periodic for a free cell,
// natural through the tether node for a tethered one). On segment k, with tau in [0, 1]
// and h_k its parameter span, a cubic spline is
//   u(tau) = (1 - tau) u_k + tau u_k+1 + h_k^2 / 6 [((1 - tau)^3 - (1 - tau)) M_k + (tau^3 - tau) M_k+1]
// in its knot values u and second derivatives M (eq A.21's unknowns). So every
// quadrature point's weight W_ij = T_ijk(x, x0) n_k dl (result_j += u_i W_ij) folds into
// four 2 x 2 blocks per target and knot, two on u and two on M:
//   DL_j(x_t) = sum_knots [u_i A_ij + M_i B_ij],
// and the subtraction of u(x_t) (DoubleLayerForm::Subtracted) needs sum_points W_ij per
// target. An application is then one spline fit (O(N)) and sums over the knots, not over
// the N x N_GL quadrature points (6 x fewer terms at N_GL = 6, and a fifth of the memory),
// vectorised over the targets.
//
// Layout: coefficient c (0-3: A_00, A_01, A_10, A_11; 4-7: B_00 .. B_11) of knot k for
// target t at [(8 k + c) paddedTargets + t]; sums at [c paddedTargets + t].
#include <capsula/contour/Contour.hpp>

#include <vector>

namespace capsula::scene2d {

/// The four basis values of a spline point at tau on a segment of parameter span h:
/// (1 - tau), tau (on the knot values), h^2/6 ((1 - tau)^3 - (1 - tau)), h^2/6 (tau^3 - tau)
/// (on the second derivatives).
inline void splineBasis(double tau, double h, double basis[4])
{
  const double s = 1.0 - tau;
  const double h26 = h * h / 6.0;
  basis[0] = s;
  basis[1] = tau;
  basis[2] = h26 * (s * s * s - s);
  basis[3] = h26 * (tau * tau * tau - tau);
}

class SplineDoubleLayer2D {
public:
  /// Zero coefficients for a contour of `numNodes` nodes (periodic: numNodes knots; tethered:
  /// numNodes + 1, the last the tether node again) and `paddedTargets` target lanes.
  void reset(int numNodes, bool periodic, int paddedTargets);

  int numKnots() const { return numKnots_; }
  int paddedTargets() const { return paddedTargets_; }
  bool periodic() const { return periodic_; }
  double* coefficients() { return coefficients_.data(); }
  double* sums() { return sums_.data(); }

  /// The knot after segment k's first: k + 1, or 0 past the end of a periodic contour.
  int rightKnot(int k) const { return periodic_ && k + 1 == numKnots_ ? 0 : k + 1; }

  /// Adds one quadrature point of segment k at tau (parameter span h) with weight W (2 x 2,
  /// [2 i + j]) for target t: the special (near-singular) points, one at a time.
  void addPoint(int t, int k, double tau, double h, const double W[4]);

  /// result[2 t + j] for the targets t < numTargets (node firstTarget + t), for the density
  /// given at the nodes (2 per node) of `contour` (the geometry the coefficients were built
  /// for); with `subtract`, the form int [u - u(x_t)] T n dl - 2 pi u(x_t).
  void apply(const contour::Contour& contour, const double* nodalDensity, bool subtract, int firstTarget,
             int numTargets, double* result) const;

private:
  int numKnots_ = 0;
  int paddedTargets_ = 0;
  bool periodic_ = true;
  std::vector<double> coefficients_;
  std::vector<double> sums_;
  // Per application (kept to avoid reallocation): knot values and second derivatives.
  mutable std::vector<double> knotData_; // [4 k + (0: u_x, 1: u_y, 2: M_x, 3: M_y)]
  mutable std::vector<double> sumX_, sumY_;
};

/// The regular pairs of the coefficients (vectorised over the targets, RegularSums2D.cpp):
/// for every segment k, its points p (pointsPerSegment each) at (px, py) with weighted
/// normal (ax, ay) = n dl and spline basis basis[4 p ..] (splineBasis), and every target t
/// with mask[k paddedTargets + t] = 1, adds W = T(x_p, x_t) a_p times the basis to the
/// coefficients of knots k and layer.rightKnot(k), and W to the sums.
void addWallDoubleLayerCoefficients2D(const double* px, const double* py, const double* ax, const double* ay,
                                      const double* basis, int pointsPerSegment, int numSegments, const double* tx,
                                      const double* ty, const double* mask, SplineDoubleLayer2D& layer);
void addFreeSpaceDoubleLayerCoefficients2D(const double* px, const double* py, const double* ax, const double* ay,
                                           const double* basis, int pointsPerSegment, int numSegments, const double* tx,
                                           const double* ty, const double* mask, SplineDoubleLayer2D& layer);

} // namespace capsula::scene2d
