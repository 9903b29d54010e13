#pragma once
// Bending moment and load of a 2D membrane in one deformed configuration, as computed by
// MembraneBending2D::evaluate (the load: BendingLoad2D.hpp).
//
// The misfit q = kappa - kappa_ref is splined against the current arc length l through its
// values at the nodes, with the ends of the tension spline (periodic for a free cell,
// not-a-knot at the tether), and d^2 q/dl^2 is that spline's second derivative: linear on
// each segment, continuous at the nodes. kappa_ref (with 'Initial shape') is splined the same
// way, for its value and slope between the nodes. kappa in the load is the contour's own
// curvature at the point.
#include <capsula/contour/Contour.hpp>
#include <capsula/contour/CubicSpline.hpp>

#include <Eigen/Core>

#include <optional>

namespace capsula::scene2d {

class MembraneBending2D;

class BendingState2D {
public:
  double modulus() const { return modulus_; }
  /// Per node (a tethered contour's node 0: the limit from segment 0), as in MembraneState2D.
  const Eigen::VectorXd& curvature() const { return curvature_; } ///< kappa
  const Eigen::VectorXd& misfit() const { return misfit_; }       ///< q = kappa - kappa_ref
  const Eigen::Matrix2Xd& load() const { return load_; }          ///< Delta f_b

  /// Delta f_b at the contour point `point` of segment k, `offset` = l - l_k into it.
  Eigen::Vector2d loadAt(const contour::ContourPoint& point, int segment, double offset) const;

  /// (k_b / 2) int q^2 dl over the current contour, q the misfit spline (exact: q^2 is a
  /// polynomial of degree 6 in l on each segment, integrated by 4-point Gauss-Legendre in l).
  double energy() const { return energy_; }

private:
  friend class MembraneBending2D;
  BendingState2D(double modulus, contour::CubicSpline misfit, std::optional<contour::CubicSpline> reference);

  double modulus_;
  contour::CubicSpline misfitSpline_;                   ///< q(l)
  std::optional<contour::CubicSpline> referenceSpline_; ///< kappa_ref(l); none: flat (0)
  Eigen::VectorXd curvature_;
  Eigen::VectorXd misfit_;
  Eigen::Matrix2Xd load_;
  double energy_ = 0.0;
};

} // namespace capsula::scene2d
