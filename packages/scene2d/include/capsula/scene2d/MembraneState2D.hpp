#pragma once
// Stretch, tension and load of a 2D membrane in one deformed configuration, as
// computed by ElasticMembrane2D::evaluate (thesis A.5.2), and its bending part when the
// membrane has one (BendingState2D.hpp): load() and loadAt() are then the sum of both loads.
#include "capsula/scene2d/BendingState2D.hpp"
#include "capsula/scene2d/HookeanLaw2D.hpp"

#include <capsula/contour/Contour.hpp>
#include <capsula/contour/CubicSpline.hpp>

#include <Eigen/Core>

#include <optional>

namespace capsula::scene2d {

class ElasticMembrane2D;

class MembraneState2D {
public:
  /// The deformed contour these values belong to (a copy).
  const contour::Contour& contour() const { return contour_; }

  /// Per node (one value per node; for a tethered contour, node 0 carries the limit
  /// from segment 0 and the other side of the tether is the value at (N - 1, t = 1)):
  const Eigen::VectorXd& stretch() const { return stretch_; }           ///< omega (eq A.38)
  const Eigen::VectorXd& tension() const { return tension_; }           ///< gamma (eq A.36)
  const Eigen::VectorXd& tensionSlope() const { return tensionSlope_; } ///< d gamma/dl (A.39)
  const Eigen::Matrix2Xd& load() const { return load_; }                ///< Delta f (eq A.4), + bending

  /// The same on segment k at the contour point (k, t), t in [0, 1], through the tension
  /// spline gamma(l) (eq A.39); this is what boundary-integral quadrature points use.
  double tensionAt(int segment, double t) const;
  double tensionSlopeAt(int segment, double t) const;
  Eigen::Vector2d loadAt(int segment, double t) const;
  /// Delta f from geometry already evaluated at (segment, t).
  Eigen::Vector2d loadAt(const contour::ContourPoint& point, int segment, double t) const;

  /// Stored energy 0.5 E int (omega - 1)^2 dl0 over the reference contour (exact on the
  /// stretch spline: the integrand is a quartic polynomial in l0 per segment).
  double elasticEnergy() const { return energy_; }

  /// The bending part (moment, its load alone, energy), or null for a membrane without one.
  const BendingState2D* bending() const { return bending_ ? &*bending_ : nullptr; }
  /// (k_b / 2) int (kappa - kappa_ref)^2 dl (BendingState2D::energy), 0 without bending.
  double bendingEnergy() const { return bending_ ? bending_->energy() : 0.0; }

  /// int Delta f dl by `points`-point Gauss-Legendre per segment (eq A.56). Zero (to
  /// quadrature error) on a free cell; on a tethered one it equals
  /// gamma t (0+) - gamma t (s_max-), the force the tether point must hold.
  Eigen::Vector2d netForce(int points) const;
  /// int (x - about) x Delta f dl (the z-component), zero on a free cell.
  double netTorque(int points, const Eigen::Vector2d& about) const;

private:
  friend class ElasticMembrane2D;
  MembraneState2D(contour::Contour current, contour::CubicSpline tensionSpline);

  contour::Contour contour_;
  contour::CubicSpline tensionSpline_; ///< gamma(l), knots at the current knot arc lengths
  Eigen::VectorXd stretch_;
  Eigen::VectorXd tension_;
  Eigen::VectorXd tensionSlope_;
  Eigen::Matrix2Xd load_;
  double energy_ = 0.0;
  std::optional<BendingState2D> bending_;
};

} // namespace capsula::scene2d
