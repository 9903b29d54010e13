#pragma once
// The initial contour of the 2D cell of Chapter 4 (thesis Fig. 4.1): an ellipse of aspect
// ratio a/b (a along the flow, x; b across it, y) and area pi L^2 (L = sqrt(ab) = 1), its
// lowest point a given height above the wall y = 0, node 0 at that lowest point.
#include "capsula/scene2d/HookeanLaw2D.hpp"
#include "capsula/scene2d/MembraneBending2D.hpp"
#include "capsula/scene2d/MembraneLawRegistry2D.hpp"

#include <capsula/contour/Contour.hpp>

#include <Eigen/Core>
#include <Teuchos_ParameterList.hpp>

#include <memory>

namespace capsula::scene2d {

struct CellSettings2D {
  double aspectRatio = 1.0;         ///< a/b
  int numberOfPoints = 256;         ///< marker points N_P = segments N_E (closed contour)
  double lowestPointHeight = 0.005; ///< y of the lowest point (the thesis's gap)
  /// Initial stretch 1 + alpha over the unstressed reference (elasticity/Prestress.hpp;
  /// the thesis's 2D study: 0).
  double prestress = 0.0;
  /// The membrane's tension law ('Cell/Membrane law', with E = 1; the thesis's: Hookean).
  std::shared_ptr<const MembraneLaw2D> membraneLaw = std::make_shared<const HookeanLaw2D>(1.0);
  /// End conditions of the tethered splines at the tether (thesis A.31-A.32: natural).
  contour::TetherEnds tetherEnds = contour::TetherEnds::Natural;
  /// Bending stiffness k_b / (E L^2) and its reference curvature (elasticity/
  /// MembraneBending2D.hpp); 0: the membrane has no bending term (the thesis's).
  double bendingModulus = 0.0;
  BendingReference2D bendingReference = BendingReference2D::Flat;
};

/// Declares Aspect ratio, Number of points, Lowest point height, Prestress, Membrane law
/// (one of `laws`, default Hookean, and the laws' keys), Tether spline ends, Bending modulus
/// and Bending reference in `cell`.
void declareCellParameters2D(Teuchos::ParameterList& cell, const MembraneLawRegistry2D& laws = builtInMembraneLaws2D());

/// Reads a validated "Cell" sublist, building its membrane law from `laws`.
CellSettings2D readCellSettings2D(const Teuchos::ParameterList& cell,
                                  const MembraneLawRegistry2D& laws = builtInMembraneLaws2D());

/// The semi-axis along the flow, a = sqrt(a/b) (L = 1).
double flowSemiAxis(const CellSettings2D& cell);

/// The marker points, counter-clockwise from the lowest point (equal steps of the ellipse
/// angle, contour::NodeSpacing::EqualEllipseAngle), centred on x = 0.
Eigen::Matrix2Xd initialCellNodes(const CellSettings2D& cell);

} // namespace capsula::scene2d
