#pragma once
// Cubic spline interpolation of one coordinate in a monotonic parameter s
// (thesis App. A.3, eqs A.15-A.25 with the A.25 fix d_k = x_k, ERRATA).
//
// The fit solves for the second derivatives M_k at the knots (eq A.21, written with the
// parameter spacings h_k = s_{k+1} - s_k where the extracted text shows coordinate
// differences) by an O(n) (cyclic) tridiagonal solve, then forms the piece coefficients
// a_k = (M_{k+1} - M_k) / (6 h_k), b_k = M_k / 2,
// c_k = (x_{k+1} - x_k) / h_k - h_k (2 M_k + M_{k+1}) / 6, d_k = x_k   (eqs A.22-A.25).
#include <cstddef>
#include <utility>
#include <vector>

namespace capsula::contour {

/// End conditions of a cubic spline (thesis A.3.1).
enum class SplineEnds {
  Periodic, ///< value, slope and second derivative continuous across the period (A.33-A.34)
  Natural,  ///< zero second derivative at both ends (A.31-A.32)
  Clamped,  ///< prescribed slopes at both ends
  NotAKnot  ///< third derivative continuous at the second and the penultimate knot
};

/// One piece p(s) = a (s - s_k)^3 + b (s - s_k)^2 + c (s - s_k) + d   (eq A.15).
struct CubicPiece {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double d = 0.0;

  double value(double ds) const { return ((a * ds + b) * ds + c) * ds + d; }
  double derivative(double ds) const { return (3.0 * a * ds + 2.0 * b) * ds + c; }
  double secondDerivative(double ds) const { return 6.0 * a * ds + 2.0 * b; }
};

/// The roots in (0, span) of p'(ds) = 3 a ds^2 + 2 b ds + c, the stationary points of a
/// piece inside it (0, 1 or 2, in `roots`, the count returned).
int stationaryPoints(const CubicPiece& p, double span, double roots[2]);

/// A piecewise cubic C^2 interpolant over strictly increasing knots s_0 < ... < s_n
/// (n pieces). Periodic splines take n values (the value at s_n is the value at s_0) and
/// repeat with period s_n - s_0; open splines take n + 1 values and extend their end
/// pieces outside [s_0, s_n].
class CubicSpline {
public:
  /// Periodic spline (free cell, eqs A.33-A.34). Needs n >= 3 pieces.
  static CubicSpline periodic(std::vector<double> knots, const std::vector<double>& values);
  /// Natural spline (tethered contour, eqs A.31-A.32). Needs n >= 1 piece.
  static CubicSpline natural(std::vector<double> knots, const std::vector<double>& values);
  /// Clamped spline with slopes dx/ds prescribed at s_0 and s_n. Needs n >= 1 piece.
  static CubicSpline clamped(std::vector<double> knots, const std::vector<double>& values, double startSlope,
                             double endSlope);
  /// Not-a-knot spline: exact for cubics without any end data. Needs n >= 3 pieces.
  static CubicSpline notAKnot(std::vector<double> knots, const std::vector<double>& values);
  /// The interpolant of samples in time (thesis Section 3.11.2: the centroid velocity as
  /// the derivative of a spline through the centroid history): the not-a-knot spline from
  /// 3 pieces on, whose slope at the newest sample is O(h^3) accurate; below that what it
  /// degenerates to, the interpolating line (1 piece) or parabola (2 pieces). Needs n >= 1
  /// piece and finite values.
  static CubicSpline interpolating(std::vector<double> knots, const std::vector<double>& values);

  SplineEnds ends() const { return ends_; }
  int numberOfPieces() const { return static_cast<int>(pieces_.size()); }
  const std::vector<double>& knots() const { return knots_; }
  const CubicPiece& piece(int k) const { return pieces_[static_cast<std::size_t>(k)]; }
  /// s_n - s_0: the period of a periodic spline, the parameter range of an open one.
  double range() const { return knots_.back() - knots_.front(); }

  /// The piece containing s and the offset s - s_k (periodic splines wrap s first).
  std::pair<int, double> locate(double s) const;

  double value(double s) const;
  double derivative(double s) const;
  double secondDerivative(double s) const;

private:
  CubicSpline(std::vector<double> knots, SplineEnds ends);
  /// Coefficients (eqs A.22-A.25) from values at all n + 1 knots and second derivatives.
  void buildPieces(const std::vector<double>& knotValues, const std::vector<double>& secondDerivatives);

  std::vector<double> knots_;
  std::vector<CubicPiece> pieces_;
  SplineEnds ends_;
};

} // namespace capsula::contour
